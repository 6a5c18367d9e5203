// SPDX-License-Identifier: BSD-3-Clause
// The depth prepass chosen by timing (vtkClusteredLightingPrepassChoice.h): which frames a
// trial renders in which mode, which it times, and what it keeps.
#include "vtkClusteredLightingPrepassChoice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

using namespace vtkClusteredLighting;

namespace
{
// What the chooser asked for in one frame.
struct Seen
{
  bool Prepass;
  bool Timed;
};

// Renders `frames` frames of one scene: each timed frame reports cost(prepass).
std::vector<Seen> RunFrames(PrepassChooser& chooser, int frames,
  const std::function<double(bool)>& cost, std::uint64_t signature = 1)
{
  std::vector<Seen> seen;
  for (int f = 0; f < frames; ++f)
  {
    const PrepassFrame frame = chooser.BeginFrame(signature);
    seen.push_back({ frame.Prepass, frame.Timed });
    if (frame.Timed)
    {
      chooser.EndFrame(cost(frame.Prepass));
    }
  }
  return seen;
}

PrepassChoiceOptions Small()
{
  PrepassChoiceOptions o;
  o.SettleFrames = 2;
  o.FramesPerBlock = 3;
  o.Margin = 0.05;
  o.RetrialInterval = 10;
  return o;
}
}

TEST(PrepassChoice, MedianOfSmallSamples)
{
  EXPECT_TRUE(std::isnan(MedianOf({})));
  EXPECT_EQ(MedianOf({ 3.0 }), 3.0);
  EXPECT_EQ(MedianOf({ 5.0, 1.0 }), 3.0);
  EXPECT_EQ(MedianOf({ 9.0, 1.0, 4.0 }), 4.0);
  EXPECT_EQ(MedianOf({ 9.0, 1.0, 4.0, 2.0 }), 3.0);
}

// Settle frames with the prepass, untimed; then a block with it (one untimed frame, three
// timed), a block without it (the same); then the chosen mode, untimed, until the next trial.
TEST(PrepassChoice, ATrialIsTwoBlocksAfterTheSettleFrames)
{
  PrepassChooser chooser(Small());
  const std::vector<Seen> seen =
    RunFrames(chooser, 2 + 8 + 10, [](bool prepass) { return prepass ? 100.0 : 150.0; });
  const std::vector<Seen> expected = { { true, false }, { true, false },   // settle
    { true, false }, { true, true }, { true, true }, { true, true },       // with
    { false, false }, { false, true }, { false, true }, { false, true } }; // without
  for (std::size_t f = 0; f < expected.size(); ++f)
  {
    EXPECT_EQ(seen[f].Prepass, expected[f].Prepass) << "frame " << f;
    EXPECT_EQ(seen[f].Timed, expected[f].Timed) << "frame " << f;
  }
  for (std::size_t f = expected.size(); f < seen.size(); ++f)
  {
    EXPECT_TRUE(seen[f].Prepass && !seen[f].Timed) << "frame " << f << " keeps the prepass";
  }
  EXPECT_TRUE(chooser.GetChoice());
  EXPECT_EQ(chooser.GetNumberOfTrials(), 1);
  EXPECT_NEAR(chooser.GetLastRatio(), 100.0 / 150.0, 1e-12);
}

TEST(PrepassChoice, DropsThePrepassWhereItCostsMoreThanItSaves)
{
  PrepassChooser chooser(Small());
  const std::vector<Seen> seen =
    RunFrames(chooser, 2 + 8 + 10, [](bool prepass) { return prepass ? 288.0 : 195.0; });
  EXPECT_FALSE(chooser.GetChoice());
  EXPECT_NEAR(chooser.GetLastRatio(), 288.0 / 195.0, 1e-12);
  for (std::size_t f = 10; f < seen.size(); ++f)
  {
    EXPECT_TRUE(!seen[f].Prepass && !seen[f].Timed) << "frame " << f;
  }
  // The next trial starts with the current choice (no prepass), then tries the prepass.
  const std::vector<Seen> next =
    RunFrames(chooser, 8, [](bool prepass) { return prepass ? 288.0 : 195.0; });
  EXPECT_FALSE(next[0].Prepass);
  EXPECT_FALSE(next[3].Prepass);
  EXPECT_TRUE(next[4].Prepass);
  EXPECT_TRUE(next[7].Prepass);
  EXPECT_FALSE(chooser.GetChoice());
  EXPECT_EQ(chooser.GetNumberOfTrials(), 2);
}

// Noise below the margin does not flip the choice; a gain above it does, in either
// direction, and the median ignores one slow frame.
TEST(PrepassChoice, TheMarginKeepsTheChoiceAgainstNoise)
{
  PrepassChooser chooser(Small());
  RunFrames(chooser, 2 + 8, [](bool prepass) { return prepass ? 100.0 : 96.0; }); // 4% faster
  EXPECT_TRUE(chooser.GetChoice());
  RunFrames(chooser, 10 + 8, [](bool prepass) { return prepass ? 100.0 : 94.0; }); // 6% faster
  EXPECT_FALSE(chooser.GetChoice());
  RunFrames(chooser, 10 + 8, [](bool prepass) { return prepass ? 97.0 : 100.0; }); // 3% slower
  EXPECT_FALSE(chooser.GetChoice());
  int frame = 0;
  RunFrames(chooser, 10 + 8,
    [&frame](bool prepass) { return prepass ? (++frame == 2 ? 1000.0 : 80.0) : 100.0; });
  EXPECT_TRUE(chooser.GetChoice()) << "one slow frame with the prepass is not its median";
  EXPECT_EQ(chooser.GetNumberOfTrials(), 4);
}

// A new signature (more lights, another viewport, changed options) starts with the
// prepass again, discards a running trial's times and settles before a new one.
TEST(PrepassChoice, ANewSceneStartsOver)
{
  PrepassChooser chooser(Small());
  RunFrames(
    chooser, 2 + 8, [](bool prepass) { return prepass ? 300.0 : 100.0; }, 1);
  EXPECT_FALSE(chooser.GetChoice());
  // Half a trial of the same scene, then the scene changes.
  RunFrames(
    chooser, 10 + 6, [](bool prepass) { return prepass ? 300.0 : 100.0; }, 1);
  std::vector<Seen> seen = RunFrames(
    chooser, 1, [](bool) { return 1.0; }, 2);
  EXPECT_EQ(chooser.GetNumberOfTrials(), 0);
  EXPECT_TRUE(std::isnan(chooser.GetLastRatio()));
  const std::vector<Seen> rest = RunFrames(
    chooser, 1 + 8, [](bool prepass) { return prepass ? 100.0 : 300.0; }, 2);
  seen.insert(seen.end(), rest.begin(), rest.end());
  EXPECT_TRUE(seen[0].Prepass && !seen[0].Timed && seen[1].Prepass && !seen[1].Timed);
  EXPECT_TRUE(seen[2].Prepass && !seen[2].Timed && seen[3].Prepass && seen[3].Timed);
  EXPECT_TRUE(!seen[6].Prepass && !seen[6].Timed);
  EXPECT_TRUE(chooser.GetChoice());
  EXPECT_EQ(chooser.GetNumberOfTrials(), 1) << "trials of this scene";
  EXPECT_NEAR(chooser.GetLastRatio(), 1.0 / 3.0, 1e-12) << "no time of the first scene kept";
}

// Frames whose time never comes (the render was cut short) leave the trial to decide on
// the times it has, or keep the choice when a mode has none.
TEST(PrepassChoice, MissingTimesDecideOnTheOthersOrNotAtAll)
{
  PrepassChooser chooser(Small());
  int f = 0;
  for (; f < 2 + 8; ++f)
  {
    const PrepassFrame frame = chooser.BeginFrame(1);
    if (frame.Timed && f != 9) // the trial's last time is lost
    {
      chooser.EndFrame(frame.Prepass ? 200.0 : 100.0);
    }
  }
  chooser.BeginFrame(1);
  EXPECT_FALSE(chooser.GetChoice());
  EXPECT_EQ(chooser.GetNumberOfTrials(), 1);

  PrepassChooser silent(Small());
  for (f = 0; f < 2 + 8 + 3; ++f)
  {
    const PrepassFrame frame = silent.BeginFrame(1);
    if (frame.Timed && frame.Prepass)
    {
      silent.EndFrame(500.0); // nothing ever reported without the prepass
    }
  }
  EXPECT_TRUE(silent.GetChoice());
  EXPECT_EQ(silent.GetNumberOfTrials(), 0);
  EXPECT_TRUE(std::isnan(silent.GetLastRatio()));
  silent.EndFrame(1.0); // no frame awaits a time: ignored
  EXPECT_EQ(silent.GetNumberOfTrials(), 0);
}
