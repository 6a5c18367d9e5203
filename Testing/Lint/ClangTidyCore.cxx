// SPDX-License-Identifier: BSD-3-Clause
// Translation unit for clang-tidy (scripts/run-clang-tidy.sh): every header of the GL-free
// core, so that the checks of .clang-tidy see all of its (inline) code. Not compiled.
#include "vtkClusteredLightingAssignment.h"
#include "vtkClusteredLightingDepthBounds.h"
#include "vtkClusteredLightingFarField.h"
#include "vtkClusteredLightingFarFieldBound.h"
#include "vtkClusteredLightingFarFieldBudget.h"
#include "vtkClusteredLightingFarFieldTree.h"
#include "vtkClusteredLightingGrid.h"
#include "vtkClusteredLightingLayout.h"
#include "vtkClusteredLightingLights.h"
#include "vtkClusteredLightingMessages.h"
#include "vtkClusteredLightingMorton.h"
#include "vtkClusteredLightingPrepassChoice.h"
#include "vtkClusteredLightingReference.h"
#include "vtkClusteredLightingShaderCode.h"
#include "vtkClusteredLightingSphereBounds.h"
#include "vtkClusteredLightingSpotBounds.h"
