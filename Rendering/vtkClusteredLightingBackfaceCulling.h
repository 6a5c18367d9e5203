// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingBackfaceCulling
 * @brief   culls the faces of closed opaque surfaces that cannot be seen (the pass's
 *          AutomaticBackfaceCulling)
 *
 * Private to the module. On llvmpipe a hidden fragment costs about what a visible one
 * does, depth prepass or not (docs/depth.md): the back faces of a closed surface were a
 * third of the frame of `Examples/Python/user_lights.py`. Where the pass can prove that
 * no back face of an actor can show, it has GL cull them, and the image is unchanged
 * (the proof: Rendering/Core/vtkClusteredLightingClosedSurface.h).
 *
 * Per render (BeginFrame), each of the render's props qualifies, at its first draw (when
 * its mapper has brought its input up to date), when all of these hold:
 *   - a plain vtkActor (vtkOpenGLActor: not a follower, LOD or assembly part) drawn by a
 *     plain vtkPolyDataMapper (vtkOpenGLPolyDataMapper: not composite, glyph or impostor
 *     mappers), with no clipping planes and no shader code or replacements of its own
 *     (which may move vertices or discard fragments; checked again at each draw, because
 *     a mapper moves VTK 9.0's deprecated per-mapper replacements to its actor's shader
 *     property only when it builds its shaders);
 *   - opaque (no translucent geometry), drawn as a surface, without textures, and with
 *     neither of vtkProperty's own face cullings;
 *   - its polydata has polygons, no triangle strips and no ghost cells (the mapper hides
 *     some), and is closed with one orientation (ComputeSurfaceClosure, about 0.2 s for a
 *     million triangles, cached per polydata until it is modified; a polydata modified in
 *     consecutive renders, an animated mesh, is not tested, and not culled, until a render
 *     in which it stays unchanged). Renders count per view, a renderer and an eye: a pass
 *     shared by several renderers, or a stereo pair's two eyes, renders a frame in several
 *     views, and a mesh modified once per frame is then modified in consecutive renders
 *     of the view that first sees each version; the other views take that view's
 *     decision for the version;
 *   - its bounding box lies beyond the near plane (IsBoxBeyondNearPlane, with the camera
 *     of this render: each eye of a stereo pair decides for itself).
 * The face culled follows from the orientation and the determinant of the map from model
 * to clip coordinates (ChooseCulledFace: a mirroring actor culls GL's front faces).
 *
 * The culling is set in the draw itself (Apply, from the render passes' SetShaderParameters,
 * which VTK calls after vtkOpenGLProperty::Render has set the actor's own culling and just
 * before each draw), only while the opaque step or the depth prepass draws (SetActive),
 * switched off after each prop (EndProp: the prepass's loop and the opaque step's own
 * opaque pass call it) and when they end (vtkOpenGLProperty::PostRender leaves it off
 * too), so nothing else drawn in the frame is culled.
 *
 * @sa vtkClusteredLightingPass vtkClusteredLightingOpaqueStep vtkClusteredLightingDepthPrepass
 */
#ifndef vtkClusteredLightingBackfaceCulling_h
#define vtkClusteredLightingBackfaceCulling_h

#include "vtkClusteredLightingClosedSurface.h" // for SurfaceClosure
#include "vtkType.h"                           // for vtkMTimeType
#include "vtkWeakPointer.h"                    // for vtkWeakPointer

#include <map>           // for std::map
#include <unordered_map> // for std::unordered_map
#include <utility>       // for std::pair

class vtkActor;
class vtkOpenGLState;
class vtkPolyData;
class vtkProp;
class vtkRenderState;
class vtkRenderer;

/// The closure of `data`'s polygons (ComputeSurfaceClosure; strips and other cells are
/// not read), computed now.
vtkClusteredLighting::SurfaceClosure vtkClusteredLightingComputeSurfaceClosure(vtkPolyData* data);

/// The face the pass would cull in `actor`'s draws under `ren`'s active camera now (+1
/// GL_BACK, -1 GL_FRONT, 0 none), by the class's rules, its closure computed now (not
/// cached): for the benchmark's stock VTK rows with the same faces culled by hand.
int vtkClusteredLightingChooseCulledFace(vtkActor* actor, vtkRenderer* ren);

class vtkClusteredLightingBackfaceCulling
{
public:
  /// Decides which props of `s` are culled in this render (none when `enabled` is false).
  void BeginFrame(const vtkRenderState* s, vtkOpenGLState* state, bool enabled);

  /// While active, the draws of props decided on cull their hidden faces (Apply).
  void SetActive(bool active);

  /// Sets GL's face culling for a draw of `prop` (the render passes' SetShaderParameters):
  /// only for props decided on in BeginFrame, and only while active.
  void Apply(vtkProp* prop);

  /// The face `prop`'s draws cull in this render (+1 GL_BACK, -1 GL_FRONT, 0 none),
  /// decided now if it was not yet (its input must be up to date).
  int GetFace(vtkProp* prop);

  /// After each prop's draws: switches the culling a draw set off again, so that the next
  /// prop is drawn as its own property says even if its mapper does not say it.
  void EndProp();

  /// Props whose hidden faces this render culled (in its draws so far).
  int GetNumberOfCulledProps() const;

private:
  /// The culled face of a prop (+1 GL_BACK, -1 GL_FRONT, 0 none) in this render.
  int Decide(vtkProp* prop);
  /// The closure of `data`, computed once per modification.
  const vtkClusteredLighting::SurfaceClosure& GetClosure(vtkPolyData* data);

  /// A view: a renderer and an eye (1 left or mono, 0 right).
  using View = std::pair<const void*, int>;
  struct CachedClosure
  {
    vtkWeakPointer<vtkPolyData> Data;
    vtkMTimeType Time = 0;            ///< the polydata's MTime when last seen
    View ChangedIn;                   ///< the view that first saw this version
    unsigned long long ChangedAt = 0; ///< that view's render (ViewRenders) in which it did
    bool Tested = false;              ///< Closure is the test of this version
    vtkClusteredLighting::SurfaceClosure Closure;
  };
  std::unordered_map<vtkPolyData*, CachedClosure> Closures;
  static constexpr int Undecided = 2;
  std::unordered_map<vtkProp*, int> Faces; ///< this render's props and their culled faces
  glm::dmat4 ClipFromWorld{ 1.0 };         ///< this render's camera
  vtkOpenGLState* State = nullptr;
  std::map<View, unsigned long long> ViewRenders; ///< BeginFrame calls per view
  View CurrentView;                               ///< this render's view
  unsigned long long CurrentViewRender = 0;       ///< its count in ViewRenders
  bool Active = false;
  bool Culled = false; ///< a draw enabled culling since SetActive(true)
};

#endif
// VTK-HeaderTest-Exclude: vtkClusteredLightingBackfaceCulling.h
