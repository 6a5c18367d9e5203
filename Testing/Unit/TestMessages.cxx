// SPDX-License-Identifier: BSD-3-Clause
// Summaries of per-light problems: grouped by source, capped, in numeric index order.
#include "vtkClusteredLightingLights.h"
#include "vtkClusteredLightingMessages.h"

#include <gtest/gtest.h>

#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace vtkClusteredLighting;

namespace
{
// The name the light collector gives light i of a set (vtkClusteredLightingLightCollection).
std::string SetLightName(const void* set, std::size_t i)
{
  std::ostringstream os;
  os << "vtkClusteredLightSet " << set << " light " << i;
  return os.str();
}

std::string RendererLightName(const void* light, std::size_t i)
{
  std::ostringstream os;
  os << "vtkLight " << light << " (renderer light " << i << ")";
  return os.str();
}

// The messages light preparation gives for `count` lights at NaN, in the given order of
// indices; each named by nameOf.
template <typename NameOf>
std::vector<std::string> NanProblems(const std::vector<std::size_t>& indices, NameOf nameOf)
{
  std::vector<LightSource> sources(indices.size());
  for (LightSource& s : sources)
  {
    s.PositionWC.x = std::numeric_limits<double>::quiet_NaN();
  }
  const PreparedLights prepared = PrepareLights(
    sources, LightPreparationOptions(), [&](std::size_t i) { return nameOf(indices[i]); });
  return prepared.Problems;
}

std::vector<std::size_t> Range(std::size_t first, std::size_t count)
{
  std::vector<std::size_t> v;
  for (std::size_t i = 0; i < count; ++i)
  {
    v.push_back(first + i);
  }
  return v;
}

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}
} // namespace

TEST(Messages, ParsesTheNamesTheCollectorGives)
{
  int object = 0;
  const ProblemSource set =
    ParseProblemSource(SetLightName(&object, 1234) + ": position (nan, 0, 0) is not finite");
  EXPECT_TRUE(set.HasIndex);
  EXPECT_EQ(set.Index, 1234u);
  EXPECT_EQ(set.Object, static_cast<const void*>(&object));
  std::ostringstream source;
  source << "vtkClusteredLightSet " << static_cast<const void*>(&object);
  EXPECT_EQ(set.Source, source.str());

  const ProblemSource light = ParseProblemSource(RendererLightName(&object, 7) + ": bad");
  EXPECT_TRUE(light.HasIndex);
  EXPECT_EQ(light.Index, 7u);
  EXPECT_EQ(light.Object, nullptr);
  EXPECT_EQ(light.Source, "the renderer's vtkLights");

  const ProblemSource plain = ParseProblemSource("light 42: color (nan, 1, 1) is not finite");
  EXPECT_TRUE(plain.HasIndex);
  EXPECT_EQ(plain.Index, 42u);

  for (const char* other : { "something odd happened", "light x: bad", "light 4b: bad",
         "vtkClusteredLightSet light 3: bad", "light 99999999999999999999999: too long" })
  {
    const ProblemSource p = ParseProblemSource(other);
    EXPECT_FALSE(p.HasIndex) << other;
    EXPECT_EQ(p.Object, nullptr) << other;
  }
}

TEST(Messages, ThousandBadLightsOfOneSetGiveCappedLinesAndOneSummary)
{
  int object = 0;
  const std::vector<std::string> problems =
    NanProblems(Range(0, 1000), [&](std::size_t i) { return SetLightName(&object, i); });
  ASSERT_EQ(problems.size(), 1000u);
  const std::vector<ProblemGroup> groups = SummarizeProblems(problems, 10);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0].NumberOfProblems, 1000u);
  EXPECT_EQ(groups[0].Object, static_cast<const void*>(&object));
  ASSERT_EQ(groups[0].Lines.size(), 11u);
  for (std::size_t i = 0; i < 10; ++i)
  {
    EXPECT_EQ(groups[0].Lines[i], problems[i]);
  }
  const std::string& summary = groups[0].Lines.back();
  EXPECT_TRUE(Contains(summary, "... and 990 more problems in " + groups[0].Source)) << summary;
  EXPECT_TRUE(Contains(summary, "(lights 10 to 999)")) << summary;
  EXPECT_TRUE(Contains(summary, "skipped")) << summary;
}

TEST(Messages, NumericOrderNotTextOrder)
{
  // The assigner keeps reported problems in a std::set<std::string>: text order, where
  // "light 10" comes before "light 2". The summary shows lights 0..4 whatever the input order.
  int object = 0;
  const std::vector<std::string> problems =
    NanProblems(Range(0, 25), [&](std::size_t i) { return SetLightName(&object, i); });
  const std::set<std::string> textOrder(problems.begin(), problems.end());
  const std::vector<std::string> shuffled(textOrder.begin(), textOrder.end());
  ASSERT_NE(shuffled, problems); // the text order differs from the index order
  const std::vector<std::string> lines = SummarizeProblemLines(shuffled, 5);
  ASSERT_EQ(lines.size(), 6u);
  for (std::size_t i = 0; i < 5; ++i)
  {
    EXPECT_EQ(lines[i], problems[i]) << "line " << i;
  }
  EXPECT_TRUE(Contains(lines[5], "... and 20 more problems")) << lines[5];
  EXPECT_TRUE(Contains(lines[5], "(lights 5 to 24)")) << lines[5];
}

TEST(Messages, CappedPerSetAndRendererLightsSeparately)
{
  int a = 0, b = 0;
  const int lights[3] = { 0, 0, 0 };
  std::vector<std::string> problems;
  for (const std::string& p :
    NanProblems(Range(0, 3), [&](std::size_t i) { return RendererLightName(lights + i, i); }))
  {
    problems.push_back(p);
  }
  for (const std::string& p :
    NanProblems(Range(0, 30), [&](std::size_t i) { return SetLightName(&a, i); }))
  {
    problems.push_back(p);
  }
  for (const std::string& p :
    NanProblems(Range(100, 12), [&](std::size_t i) { return SetLightName(&b, i); }))
  {
    problems.push_back(p);
  }
  const std::vector<ProblemGroup> groups = SummarizeProblems(problems, 10);
  ASSERT_EQ(groups.size(), 3u);
  // In the order the sources first appear.
  EXPECT_EQ(groups[0].Source, "the renderer's vtkLights");
  EXPECT_EQ(groups[0].Lines.size(), 3u); // 3 <= 10: all shown, no summary
  EXPECT_EQ(groups[0].Object, nullptr);
  EXPECT_EQ(groups[1].Object, static_cast<const void*>(&a));
  EXPECT_EQ(groups[1].NumberOfProblems, 30u);
  ASSERT_EQ(groups[1].Lines.size(), 11u);
  EXPECT_TRUE(Contains(groups[1].Lines.back(), "... and 20 more problems in " + groups[1].Source));
  EXPECT_EQ(groups[2].Object, static_cast<const void*>(&b));
  ASSERT_EQ(groups[2].Lines.size(), 11u);
  EXPECT_TRUE(Contains(groups[2].Lines.back(), "... and 2 more problems"));
  EXPECT_TRUE(Contains(groups[2].Lines.back(), "(lights 110 to 111)"));
}

TEST(Messages, ExactlyAtTheCapNoSummaryOneOverOneLine)
{
  int object = 0;
  auto name = [&](std::size_t i) { return SetLightName(&object, i); };
  EXPECT_EQ(SummarizeProblemLines(NanProblems(Range(0, 10), name), 10).size(), 10u);
  const std::vector<std::string> eleven =
    SummarizeProblemLines(NanProblems(Range(0, 11), name), 10);
  ASSERT_EQ(eleven.size(), 11u);
  EXPECT_TRUE(Contains(eleven.back(), "... and 1 more problem in ")) << eleven.back();
  EXPECT_TRUE(Contains(eleven.back(), "(light 10)")) << eleven.back();
  EXPECT_TRUE(Contains(eleven.back(), "that light is skipped too")) << eleven.back();
  EXPECT_TRUE(SummarizeProblems({}, 10).empty());
}

TEST(Messages, ZeroCapGivesOnlyTheSummary)
{
  int object = 0;
  const std::vector<std::string> lines = SummarizeProblemLines(
    NanProblems(Range(0, 4), [&](std::size_t i) { return SetLightName(&object, i); }), 0);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(Contains(lines[0], "... and 4 more problems")) << lines[0];
}

TEST(Messages, UnparsedMessagesAreKeptAsGroupsOfTheirOwn)
{
  const std::vector<std::string> problems = { "light 3: bad", "odd: one", "light 1: bad",
    "odd: two", "another kind of message" };
  const std::vector<ProblemGroup> groups = SummarizeProblems(problems, 10);
  ASSERT_EQ(groups.size(), 3u);
  ASSERT_EQ(groups[0].Lines.size(), 2u);
  EXPECT_EQ(groups[0].Lines[0], "light 1: bad");
  EXPECT_EQ(groups[0].Lines[1], "light 3: bad");
  ASSERT_EQ(groups[1].Lines.size(), 2u); // "odd": same name, kept in their order
  EXPECT_EQ(groups[1].Lines[0], "odd: one");
  EXPECT_EQ(groups[1].Lines[1], "odd: two");
  ASSERT_EQ(groups[2].Lines.size(), 1u);
  std::size_t total = 0;
  for (const ProblemGroup& g : groups)
  {
    total += g.NumberOfProblems;
  }
  EXPECT_EQ(total, problems.size());
}
