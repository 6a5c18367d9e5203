// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingRendererObjects
 * @brief   one VTK object per renderer, made on first use, as vtkOpenGLRenderer keeps its own
 *
 * Private to the module. vtkOpenGLRenderer keeps one SSAO pass and one FXAA filter of its
 * own; under a render pass they are the pass's to keep. One pass may serve several
 * renderers, in several windows (one GL context each), and these objects hold GL
 * resources sized to one viewport, so they are kept per renderer here as well: made on
 * first use, released with their window (Release) or with this object, and released then
 * dropped once their renderer is deleted; always in their own window's context.
 *
 * T is a vtkObject with New(); the releaser frees its GL resources in a window.
 */
#ifndef vtkClusteredLightingRendererObjects_h
#define vtkClusteredLightingRendererObjects_h

#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <map> // for std::map

template <typename T>
class vtkClusteredLightingRendererObjects
{
public:
  using Releaser = void (*)(T* object, vtkWindow* window);

  explicit vtkClusteredLightingRendererObjects(Releaser release)
    : ReleaseObject(release)
  {
  }

  /// Releases every object's GL resources in its own window.
  ~vtkClusteredLightingRendererObjects() { this->Release(nullptr); }

  vtkClusteredLightingRendererObjects(const vtkClusteredLightingRendererObjects&) = delete;
  vtkClusteredLightingRendererObjects& operator=(
    const vtkClusteredLightingRendererObjects&) = delete;

  /// The object of `ren`, made on first use.
  T* Get(vtkRenderer* ren)
  {
    this->DropDeleted();
    Entry& entry = this->Entries[ren];
    if (!entry.Object)
    {
      entry.Renderer = ren;
      entry.Object = vtkSmartPointer<T>::New();
    }
    entry.Window = ren->GetRenderWindow();
    return entry.Object;
  }

  /// Releases the GL resources of the objects last used in `window` (every object when
  /// `window` is null: their own windows are used).
  void Release(vtkWindow* window)
  {
    this->DropDeleted();
    for (auto& e : this->Entries)
    {
      vtkWindow* own = e.second.Window;
      if (own && (!window || own == window))
      {
        this->ReleaseIn(e.second.Object, own);
      }
    }
  }

private:
  struct Entry
  {
    vtkWeakPointer<vtkRenderer> Renderer;
    vtkWeakPointer<vtkWindow> Window;
    vtkSmartPointer<T> Object;
  };

  /// Objects of deleted renderers: released in their window if it still exists (a
  /// deleted window has freed every GL resource made in its context already), dropped.
  void DropDeleted()
  {
    for (auto it = this->Entries.begin(); it != this->Entries.end();)
    {
      if (it->second.Renderer)
      {
        ++it;
        continue;
      }
      if (it->second.Window)
      {
        this->ReleaseIn(it->second.Object, it->second.Window);
      }
      it = this->Entries.erase(it);
    }
  }

  /// Releases in the window's own context: some of VTK's objects delete their GL names in
  /// whatever context is current (vtkOpenGLFXAAFilter's timer queries, for one), which
  /// may be another window's, with names of its own.
  void ReleaseIn(T* object, vtkWindow* window)
  {
    vtkOpenGLRenderWindow* w = vtkOpenGLRenderWindow::SafeDownCast(window);
    if (w)
    {
      w->PushContext();
    }
    this->ReleaseObject(object, window);
    if (w)
    {
      w->PopContext();
    }
  }

  Releaser ReleaseObject;
  std::map<vtkRenderer*, Entry> Entries;
};

#endif
