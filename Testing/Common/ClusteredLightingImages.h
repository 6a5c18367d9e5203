// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ClusteredLightingImages.h
 * @brief Reading back a render window: as floats for comparisons, or as a PNG file.
 *
 * Shared by the examples, the benchmark and the GL tests. Both read the back buffer of the
 * last render (no re-render), so call them right after vtkRenderWindow::Render().
 */
#ifndef ClusteredLightingImages_h
#define ClusteredLightingImages_h

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <cstddef>
#include <string>
#include <vector>

namespace ClusteredLightingImages
{
/// RGB of the whole window, row-major from the bottom, each channel in [0, 1].
inline std::vector<float> CaptureRGB(vtkRenderWindow* rw)
{
  vtkNew<vtkWindowToImageFilter> w2i;
  w2i->SetInput(rw);
  w2i->SetInputBufferTypeToRGB();
  w2i->ReadFrontBufferOff();
  w2i->ShouldRerenderOff();
  w2i->Update();
  vtkUnsignedCharArray* a =
    vtkUnsignedCharArray::SafeDownCast(w2i->GetOutput()->GetPointData()->GetScalars());
  std::vector<float> out(static_cast<std::size_t>(a->GetNumberOfValues()));
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    out[static_cast<std::size_t>(i)] = a->GetValue(i) / 255.0f;
  }
  return out;
}

/// Writes the window's last image to a PNG file.
inline void WritePNG(vtkRenderWindow* rw, const std::string& path)
{
  vtkNew<vtkWindowToImageFilter> w2i;
  w2i->SetInput(rw);
  w2i->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(w2i->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->Write();
}
/// Writes RGB floats in [0, 1] (row-major from the bottom, as CaptureRGB) to a PNG file.
inline void WriteRGBPNG(
  const std::vector<float>& rgb, int width, int height, const std::string& path)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  unsigned char* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (std::size_t i = 0; i < rgb.size() && i < 3 * static_cast<std::size_t>(width) * height; ++i)
  {
    const float v = rgb[i] < 0.0f ? 0.0f : (rgb[i] > 1.0f ? 1.0f : rgb[i]);
    out[i] = static_cast<unsigned char>(v * 255.0f + 0.5f);
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
}
} // namespace ClusteredLightingImages

#endif
