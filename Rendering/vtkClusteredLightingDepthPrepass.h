// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingDepthPrepass
 * @brief   depth-only render of a renderer's opaque geometry, and its depth readback
 *
 * Private to the module; used by vtkClusteredLightingPass before the light assignment:
 *
 *   1. RenderDepth(): the viewport and scissor as vtkCameraPass sets them, the depth
 *      cleared when the renderer would clear it, colour writes masked, then every visible
 *      prop's opaque geometry. The props carry this pass (not the clustered pass) in their
 *      render-pass keys meanwhile, so the mappers draw VTK's own program, without any
 *      clustered code: a uniform that skips the light walk is not enough, because a
 *      software rasterizer (llvmpipe) runs both sides of a branch under a mask, far-field
 *      texture reads included. A mapper switching between its two programs rebuilds its
 *      shader source, but VTK's shader cache keeps both compiled programs.
 *   2. ReadDepth(): the viewport's window depths, the input of depth-aware clusters
 *      (Rendering/Core/vtkClusteredLightingDepthBounds.h). A multisampled depth buffer
 *      cannot be read back and would not be enough (a fragment is shaded at the pixel
 *      centre, whose depth may match none of the samples'): there RenderDepth draws
 *      through vtkClusteredLightingSampleDepths, which records each pixel's range of
 *      fragment depths, and ReadDepth takes that.
 *   3. The clustered pass then renders its delegate with the renderer's depth buffer
 *      preserved: the camera pass clears colour only, and every opaque fragment behind the
 *      visible surface fails the depth test (GL_LEQUAL, VTK's default) before it is shaded.
 *
 * Both programs declare `invariant gl_Position` (here and in the clustered pass's shader
 * hook), so the same vertex shader code gives the same depth in both, as the equal depth
 * test needs.
 *
 * A frame whose prepass would draw what the last one drew (ComputeReuseSignature: the
 * same renderer, framebuffer, viewport, camera and props, none of whose data, transforms
 * or properties changed) copies the last depths back instead
 * (vtkClusteredLightingSavedDepth, one per renderer) and keeps the last readback: a still
 * camera over moving lights, or a re-render of an unchanged scene, pays one depth copy
 * instead of a second geometry pass. Props whose depths could change without a
 * modification time showing it make the signature 0 (no reuse): anything but a plain
 * vtkActor (or ParaView's vtkPVLODActor) with a vtkPolyDataMapper drawing one piece or a
 * vtkCompositePolyDataMapper2 (its blocks' times and display attributes hashed too), or an
 * overlay that writes no depth
 * (2D actors with VTK's polydata mapper, text, scalar bars, corner annotations); shader
 * replacements or UpdateShaderEvent observers (uniforms set per draw); and a depth
 * buffer the prepass does not clear.
 *
 * While rendering it notes what each program writes to depth (NoteProgram): VTK's
 * coincident-topology offset (gl_FragDepth = gl_FragCoord.z + cOffset / 65000) widens
 * the readback's margin by the largest |cOffset|; any other gl_FragDepth write (impostor
 * spheres and tubes, or VTK 9.2's offset with a non-zero slope factor cFactor) makes the
 * depths unusable for depth-aware clusters this frame.
 *
 * @sa vtkClusteredLightingPass
 */
#ifndef vtkClusteredLightingDepthPrepass_h
#define vtkClusteredLightingDepthPrepass_h

#include "vtkClusteredLightingDepthBounds.h" // for DepthImage

#include "vtkOpenGLRenderPass.h"

#include <cstdint> // for std::uint64_t
#include <map>     // for the programs' facts
#include <string>  // for std::string
#include <vector>  // for std::vector

class vtkClusteredLightingBackfaceCulling;
class vtkClusteredLightingSampleDepths;
class vtkClusteredLightingSavedDepth;
class vtkOpenGLRenderWindow;
class vtkRenderState;
class vtkShaderProgram;

class vtkClusteredLightingDepthPrepass : public vtkOpenGLRenderPass
{
public:
  static vtkClusteredLightingDepthPrepass* New();
  vtkTypeMacro(vtkClusteredLightingDepthPrepass, vtkOpenGLRenderPass)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Renders the opaque props of `s` depth-only (RenderDepth, without waiting).
  void Render(const vtkRenderState* s) override;

  /// Renders the opaque props of `s` depth-only. With `finish`, waits for the GPU so that
  /// the render time is the prepass's own (a deferred renderer would otherwise bill it to
  /// the next GL work). With `sampleDepths` and a multisampled framebuffer, records the
  /// depths of the fragments through it (for ReadDepth). Returns the number of props
  /// rendered. With `saved` (the renderer's) and a non-zero `reuse`
  /// (ComputeReuseSignature), saves the depths for RestoreDepth in a later frame.
  int RenderDepth(const vtkRenderState* s, vtkOpenGLRenderWindow* rw, bool finish,
    vtkClusteredLightingSampleDepths* sampleDepths = nullptr,
    vtkClusteredLightingSavedDepth* saved = nullptr, std::uint64_t reuse = 0);

  /// Instead of RenderDepth: copies the depths RenderDepth last saved back into the
  /// framebuffer when `reuse` (non-zero, ComputeReuseSignature) equals that frame's and
  /// the copy can be exact. False (nothing done; RenderDepth draws) otherwise. `finish`
  /// as for RenderDepth. The last readback (ReadDepth) stays valid.
  bool RestoreDepth(const vtkRenderState* s, vtkOpenGLRenderWindow* rw, bool finish,
    vtkClusteredLightingSavedDepth* saved, std::uint64_t reuse);

  /// A hash of what the prepass's depths depend on, for RenderDepth's `reuse`; 0 when
  /// they may depend on something it cannot see (see above). `record`: the depths are to
  /// be recorded through vtkClusteredLightingSampleDepths. Brings the props' inputs up to
  /// date (as their mappers would when drawn). `why` (optional) says what made it 0.
  /// `culling` (optional): each prop's culled face in this render is part of the hash (a
  /// prepass drawn with other faces may hold a back face's depth where a tie left it).
  static std::uint64_t ComputeReuseSignature(const vtkRenderState* s, vtkOpenGLRenderWindow* rw,
    bool record, std::string* why = nullptr,
    vtkClusteredLightingBackfaceCulling* culling = nullptr);

  /// Whether the last RestoreDepth copied the depths back (RenderDepth clears it).
  bool GetReused() const { return this->Reused; }
  /// Whether this frame's depths are kept for the next (saved by RenderDepth, or
  /// restored by RestoreDepth).
  bool GetKept() const
  {
    return this->FrameSignature != 0 && this->SavedSignature == this->FrameSignature;
  }

  /// Reads the viewport's depth back (from the framebuffer RenderDepth drew into), or
  /// takes the multisampled record of RenderDepth.
  /// False (with GetProblem()) when it cannot: a multisampled framebuffer whose depths
  /// were not recorded (or a program that did not record them), or a GL error.
  bool ReadDepth(vtkOpenGLRenderWindow* rw);

  /// The last readback (valid after ReadDepth returned true).
  vtkClusteredLighting::DepthImage GetImage() const;

  /// Declares `invariant gl_Position` in the vertex shader (AddInvariantPosition).
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;

  /// Notes the depth writes of every program drawn (NoteProgram).
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao = nullptr) override;

  /// The culling of hidden faces that each draw applies (the pass's
  /// AutomaticBackfaceCulling; nullptr: none), not owned.
  void SetBackfaceCulling(vtkClusteredLightingBackfaceCulling* culling)
  {
    this->BackfaceCulling = culling;
  }

  /// Adds `invariant gl_Position;` once, after the vertex shader's //VTK::System::Dec or
  /// its last #extension directive (vtkClusteredLighting::InsertDeclarations).
  static void AddInvariantPosition(std::string& vertexShader);

  /// Adds the pixel-centre depth output `gl_FragData[1] = (z, -z, 0, 1)` at the start of
  /// main() (vtkClusteredLightingSampleDepths records it), where the shader writes
  /// gl_FragData[0] and not yet gl_FragData[1].
  static void AddDepthOutput(std::string& fragmentShader);

  /// How far from its pixel's centre a fragment of `s`'s visible props may have its
  /// position (DepthBoundsOptions::PixelSlack), in pixels: 0 where no visible actor (an
  /// assembly's parts included) may draw lines or points; otherwise half the widest of
  /// those actors' LineWidth and PointSize (at least 1) plus one pixel for the
  /// rasterizer's rules and multisampled coverage. An actor may draw lines or points
  /// with a representation other than surface, edges or vertices shown, line or vertex
  /// cells in its polydata (a composite's leaves), or a mapper other than VTK's polydata
  /// and composite polydata mappers.
  static double ComputePixelSlack(const vtkRenderState* s);

  /// Where the fragments of the state's visible translucent props may be on screen
  /// (DepthBoundsOptions::TranslucentRects): the rectangle of each one's box under
  /// `wcvc`, `vcdc` (vtkClusteredLighting::ProjectBoxToViewport), the box being its
  /// mapper's bounds under the actor's matrix. Only a plain actor (vtkOpenGLActor, or
  /// ParaView's vtkPVLODActor with the mapper it draws in this render) whose mapper is
  /// VTK's polydata or composite polydata mapper and whose shader property holds no
  /// shader code or replacements keeps its fragments' positions inside that box; for any
  /// other translucent prop (impostor mappers, followers, VTK's LOD actors, assemblies,
  /// custom shaders), `rects` is left empty: translucent fragments may be anywhere. A box
  /// reaching behind the camera gives the whole viewport. `depths` gets the view depths of
  /// each box (DepthBoundsOptions::TranslucentDepths), one per rectangle. `translucent`
  /// tells whether any visible prop has translucent geometry.
  static void ComputeTranslucentRects(const vtkRenderState* s, const glm::dmat4& wcvc,
    const glm::dmat4& vcdc, bool& translucent, std::vector<glm::dvec4>& rects,
    std::vector<glm::dvec2>& depths);

  double GetMaximumCoincidentOffset() const { return this->MaxCoincidentOffset; }
  bool GetUnknownDepthWrites() const { return this->UnknownDepthWrites; }
  const std::string& GetProblem() const { return this->Problem; }
  double GetRenderTime() const { return this->RenderTime; } ///< ms, render and readback

protected:
  vtkClusteredLightingDepthPrepass() = default;
  ~vtkClusteredLightingDepthPrepass() override = default;

private:
  vtkClusteredLightingBackfaceCulling* BackfaceCulling = nullptr;
  vtkClusteredLightingDepthPrepass(const vtkClusteredLightingDepthPrepass&) = delete;
  void operator=(const vtkClusteredLightingDepthPrepass&) = delete;

  void NoteProgram(vtkShaderProgram* program);

  /// What a program's fragment source says about depth (NoteProgram), kept by the hash of
  /// its sources (vtkShaderProgram::GetMD5Hash, set by VTK's shader cache): the source is
  /// the same every frame, and reading it is a copy and two scans of some 20 KB per draw.
  struct ProgramFacts
  {
    bool Records = false;      ///< has AddDepthOutput's line
    std::size_t Writes = 0;    ///< gl_FragDepth assignments
    bool KnownOffsets = false; ///< every one is VTK's coincident-topology offset
    bool SlopeFactor = false;  ///< some of them are VTK 9.2's, with cFactor
  };
  static ProgramFacts ReadProgramFacts(const std::string& fragmentSource);
  std::map<std::string, ProgramFacts> Facts;

  double MaxCoincidentOffset = 0.0;
  bool UnknownDepthWrites = false;
  bool UnrecordedDepths = false; ///< a program drawn without AddDepthOutput's line
  bool Multisampled = false;     ///< the framebuffer RenderDepth drew into has samples
  bool Recorded = false;         ///< this frame's depths come from the sample record
  std::string SampleProblem;     ///< why the sample depths were not recorded
  std::vector<float> Depth;
  std::vector<float> DepthMax;      ///< with a sample record: each pixel's deepest fragment
  std::vector<unsigned int> Packed; ///< the packed depth-stencil read (3 MiB at 1024x768)
  int Size[2] = { 0, 0 };
  int Origin[2] = { 0, 0 };
  std::string Problem;
  double RenderTime = 0.0;

  // Reuse (RenderDepth's `reuse`).
  std::uint64_t SavedSignature = 0; ///< of the frame whose depths were last saved (0: none)
  std::uint64_t FrameSignature = 0; ///< this frame's `reuse` (0 without a saved depth)
  std::uint64_t DepthSignature = 0; ///< of the frame whose readback Depth holds (0: none)
  bool Reused = false;
};

#endif
