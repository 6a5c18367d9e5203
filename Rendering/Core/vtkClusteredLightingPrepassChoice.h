// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingPrepassChoice.h
 * @brief GL-free choice of the depth prepass by timing it: kept only where it pays.
 *
 * The depth prepass (and the depth-aware clusters that need its depths) costs one more
 * pass over the opaque geometry and saves the shading of hidden fragments and the walk
 * of lights that do not reach the visible depths. Which side wins depends on the scene
 * (how much geometry is hidden, how many lights reach a cluster) and on the device (the
 * cost of geometry against the cost of shading, which differs by orders of magnitude
 * between a software rasterizer and a GPU): on llvmpipe the bunny's 1.1 M triangles with
 * 64 lights render 1.47x slower with it, the house 1.27x faster (docs/depth.md). No fixed
 * rule fits every device, so the pass measures both on the device it runs on.
 *
 * A trial is two blocks of frames, the current choice first, then the other. Each block
 * starts with one frame that is not timed (the switch rebuilds the mappers' shader sources
 * and the light assignment), then FramesPerBlock timed frames. The caller times each
 * timed frame from the end of all earlier GL work to the end of its own (glFinish on both
 * sides), so the times are the device's, whatever it is. After the trial the choice
 * changes only if the other side's median is below the current side's median by more than
 * Margin (so noise does not make it flip back and forth).
 *
 * When a trial runs:
 *  - SettleFrames frames after the first frame, or after the scene's signature changed
 *    (the caller's hash of what moves the break-even: the number of lights in powers of
 *    two, the props, the viewport, the pass's options): the first frames compile shaders.
 *    A new signature starts with the prepass, as the pass's options configure it, so what
 *    a user sets is what the next frames render until a trial says otherwise.
 *  - Every RetrialInterval frames after a trial: the camera may have moved to where the
 *    other side wins.
 * A trial costs its frames in the slower mode (at most 1 + FramesPerBlock per interval)
 * and two glFinish per timed frame.
 *
 * The chooser only says which mode a frame uses; images of both modes agree to the
 * pass's stated bounds (bit for bit for lights with an explicit radius and windowed
 * falloff), so a change of choice between frames changes no image beyond that.
 */
#ifndef vtkClusteredLightingPrepassChoice_h
#define vtkClusteredLightingPrepassChoice_h

#include <algorithm> // for std::nth_element
#include <cmath>     // for NAN
#include <cstddef>   // for std::size_t
#include <cstdint>   // for std::uint64_t
#include <vector>    // for std::vector

namespace vtkClusteredLighting
{

/// When and how long the trials run.
struct PrepassChoiceOptions
{
  int SettleFrames = 3;      ///< frames of a new signature before its first trial
  int FramesPerBlock = 3;    ///< timed frames per mode in a trial
  double Margin = 0.05;      ///< relative gain needed to change the choice
  int RetrialInterval = 600; ///< frames between the end of a trial and the next
};

/// What one frame does.
struct PrepassFrame
{
  bool Prepass = true; ///< render the depth prepass (and depth-aware clusters)
  bool Timed = false;  ///< time this frame and report it with EndFrame
};

/// Median of a small sample (NaN when empty).
inline double MedianOf(std::vector<double> v)
{
  if (v.empty())
  {
    return NAN;
  }
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
  double m = v[mid];
  if (v.size() % 2 == 0)
  {
    m = 0.5 * (m + *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid)));
  }
  return m;
}

/// Chooses per renderer between rendering with the depth prepass and without it, from
/// frames timed side by side (see the file's comment).
class PrepassChooser
{
public:
  explicit PrepassChooser(const PrepassChoiceOptions& options = PrepassChoiceOptions())
    : Options(options)
  {
  }

  /// The mode of the next frame of a scene with this signature. Call once per frame that
  /// could use the prepass; call EndFrame after it when the result says Timed.
  PrepassFrame BeginFrame(std::uint64_t signature)
  {
    if (this->Decide) // the trial's last time never came: decide on the others
    {
      this->MakeChoice();
    }
    if (!this->HasSignature || signature != this->Signature)
    {
      this->HasSignature = true;
      this->Signature = signature;
      this->Choice = true;
      this->Trials = 0;
      this->LastRatio = NAN;
      this->Restart(this->Options.SettleFrames);
    }
    PrepassFrame frame;
    frame.Prepass = this->Choice;
    this->Pending = -1;
    if (this->Countdown > 0)
    {
      --this->Countdown;
      return frame;
    }
    const int block = 1 + this->Options.FramesPerBlock;
    const bool second = this->Step >= block;
    frame.Prepass = second ? !this->Choice : this->Choice;
    frame.Timed = this->Step % block != 0;
    this->Pending = frame.Timed ? (frame.Prepass ? 1 : 0) : -1;
    if (++this->Step == 2 * block)
    {
      this->Finish();
    }
    return frame;
  }

  /// The time of the last frame BeginFrame said to time (in any unit, the same each time).
  /// Ignored when that frame was not timed or already reported.
  void EndFrame(double time)
  {
    if (this->Pending < 0)
    {
      return;
    }
    (this->Pending ? this->With : this->Without).push_back(time);
    this->Pending = -1;
    if (this->Decide)
    {
      this->MakeChoice();
    }
  }

  /// True while the prepass is chosen (true before any trial).
  bool GetChoice() const { return this->Choice; }
  /// Median frame time with the prepass over the median without it, in the last trial
  /// of this signature that timed both; NaN before any.
  double GetLastRatio() const { return this->LastRatio; }
  /// Trials of this signature completed (both modes timed).
  int GetNumberOfTrials() const { return this->Trials; }

private:
  void Restart(int countdown)
  {
    this->Countdown = countdown;
    this->Step = 0;
    this->Decide = false;
    this->With.clear();
    this->Without.clear();
  }

  // The trial's last frame has begun; the choice is made when its time arrives (or at
  // once when it was not timed).
  void Finish()
  {
    this->Decide = true;
    if (this->Pending < 0)
    {
      this->MakeChoice();
    }
  }

  void MakeChoice()
  {
    const double with = MedianOf(this->With);
    const double without = MedianOf(this->Without);
    if (with > 0.0 && without > 0.0)
    {
      ++this->Trials;
      this->LastRatio = with / without;
      const double current = this->Choice ? with : without;
      const double other = this->Choice ? without : with;
      if (other < current * (1.0 - this->Options.Margin))
      {
        this->Choice = !this->Choice;
      }
    }
    this->Restart(this->Options.RetrialInterval);
  }

  PrepassChoiceOptions Options;
  bool HasSignature = false;
  std::uint64_t Signature = 0;
  bool Choice = true;
  int Countdown = 0; ///< frames before the next trial
  int Step = 0;      ///< frame within the trial
  int Pending = -1;  ///< mode of the frame whose time is awaited: 1 with, 0 without, -1 none
  bool Decide = false;
  std::vector<double> With, Without;
  double LastRatio = NAN;
  int Trials = 0;
};

} // namespace vtkClusteredLighting

#endif
