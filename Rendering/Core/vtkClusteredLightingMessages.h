// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingMessages.h
 * @brief GL-free summaries of per-light problems: a few lines per light source, not one per
 * light.
 *
 * Light preparation (vtkClusteredLightingLights.h) gives one message per skipped light,
 * "<who>: <problem>; the light is skipped", where <who> names the light:
 *
 *   "vtkClusteredLightSet 0x55d0c2a0 light 12"   light 12 of a light set
 *   "vtkLight 0x55d0c310 (renderer light 3)"      a vtkLight of the renderer
 *   "light 7"                                     a light of an unnamed list
 *
 * A set of 1,000 broken lights would print 1,000 lines. SummarizeProblems() groups the
 * messages by their source (one group per light set, one for all the renderer's vtkLights,
 * one for unnamed lights; a message of any other form is a group of its own), keeps the
 * first few of each group in the numeric order of the light indices (not in the text order
 * of the messages, where "light 10" comes before "light 2"), and ends a group that had more
 * with one line:
 *
 *   "... and 990 more problems in vtkClusteredLightSet 0x55d0c2a0 (lights 10 to 999); those
 *    lights are skipped too"
 *
 * Each group also carries the address of the light set it belongs to (parsed back from
 * the message), so that a caller can raise the lines on that set as well.
 */
#ifndef vtkClusteredLightingMessages_h
#define vtkClusteredLightingMessages_h

#include <algorithm> // for std::stable_sort
#include <cctype>    // for std::isdigit
#include <cstddef>   // for std::size_t
#include <sstream>   // for std::istringstream
#include <string>    // for std::string
#include <utility>   // for std::move
#include <vector>    // for std::vector

namespace vtkClusteredLighting
{

/// How many problems of one source are shown before the rest are summarized in one line.
constexpr std::size_t DefaultMaximumProblemsPerSource = 10;

/// Where a problem message comes from, parsed from the name that starts it.
struct ProblemSource
{
  std::string Source;           ///< the group's name, used in the summary line
  const void* Object = nullptr; ///< the light set's address (null for other sources)
  bool HasIndex = false;        ///< whether Index was found
  unsigned long long Index = 0; ///< the light's index within its source
};

/// The messages of one source, ready to print: at most maxPerSource problems in the
/// order of their light indices, then one summary line if there were more.
struct ProblemGroup
{
  std::string Source;
  const void* Object = nullptr;     ///< the light set's address (null for other sources)
  std::vector<std::string> Lines;   ///< what to report, in order
  std::size_t NumberOfProblems = 0; ///< every problem of the source, shown or summarized
};

namespace Detail
{
/// Reads the decimal number that starts text at pos; false when there is none.
inline bool ReadIndex(const std::string& text, std::size_t pos, unsigned long long& index)
{
  if (pos >= text.size() || !std::isdigit(static_cast<unsigned char>(text[pos])))
  {
    return false;
  }
  index = 0;
  const unsigned long long limit = (~0ULL - 9) / 10; // 10 * index + 9 still fits
  for (; pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos])); ++pos)
  {
    if (index > limit)
    {
      return false; // does not fit: keep the message where it is
    }
    index = 10 * index + static_cast<unsigned long long>(text[pos] - '0');
  }
  return true;
}

inline bool StartsWith(const std::string& text, const char* prefix)
{
  return text.compare(0, std::char_traits<char>::length(prefix), prefix) == 0;
}
} // namespace Detail

/**
 * Parses the name at the start of a problem message (the text before the first ": ").
 * Light sets: Source "vtkClusteredLightSet <address>", Object the address, Index the light.
 * Renderer lights: Source "the renderer's vtkLights", Index the renderer light number.
 * Unnamed lights ("light 7"): Source "the lights", Index 7. Anything else: Source is the
 * whole name, without an index.
 */
inline ProblemSource ParseProblemSource(const std::string& problem)
{
  ProblemSource out;
  const std::size_t colon = problem.find(": ");
  const std::string who = problem.substr(0, colon);
  out.Source = who;
  if (Detail::StartsWith(who, "vtkClusteredLightSet "))
  {
    const std::size_t light = who.rfind(" light ");
    const std::size_t first = std::char_traits<char>::length("vtkClusteredLightSet ");
    if (light != std::string::npos && light > first && Detail::ReadIndex(who, light + 7, out.Index))
    {
      out.HasIndex = true;
      out.Source = who.substr(0, light);
      // The address as operator<< wrote it; operator>> reads that form back.
      std::istringstream address(who.substr(first, light - first));
      void* object = nullptr;
      if (address >> object)
      {
        out.Object = object;
      }
    }
  }
  else if (Detail::StartsWith(who, "vtkLight "))
  {
    const std::size_t light = who.rfind("(renderer light ");
    if (light != std::string::npos && Detail::ReadIndex(who, light + 16, out.Index))
    {
      out.HasIndex = true;
      out.Source = "the renderer's vtkLights";
    }
  }
  else if (Detail::StartsWith(who, "light ") && Detail::ReadIndex(who, 6, out.Index) &&
    who.find_first_not_of("0123456789", 6) == std::string::npos)
  {
    out.HasIndex = true;
    out.Source = "the lights";
  }
  return out;
}

/**
 * Groups problem messages by source (in the order each source first appears), sorts each
 * group by light index, keeps the first maxPerSource messages of each group and replaces
 * the rest with one line "... and N more problems in <source> (lights A to B); those
 * lights are skipped too". maxPerSource 0 keeps no message, only the summary line.
 * Messages without an index keep their order, after the indexed ones of their group.
 */
inline std::vector<ProblemGroup> SummarizeProblems(
  const std::vector<std::string>& problems, std::size_t maxPerSource)
{
  struct Entry
  {
    ProblemSource Parsed;
    const std::string* Text;
  };
  std::vector<std::vector<Entry>> grouped;
  std::vector<ProblemGroup> groups;
  for (const std::string& problem : problems)
  {
    Entry entry{ ParseProblemSource(problem), &problem };
    std::size_t g = 0;
    while (g < groups.size() &&
      (groups[g].Source != entry.Parsed.Source || groups[g].Object != entry.Parsed.Object))
    {
      ++g;
    }
    if (g == groups.size())
    {
      groups.emplace_back();
      groups.back().Source = entry.Parsed.Source;
      groups.back().Object = entry.Parsed.Object;
      grouped.emplace_back();
    }
    grouped[g].push_back(std::move(entry));
  }
  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    std::vector<Entry>& entries = grouped[g];
    std::stable_sort(entries.begin(), entries.end(),
      [](const Entry& a, const Entry& b)
      {
        if (a.Parsed.HasIndex != b.Parsed.HasIndex)
        {
          return a.Parsed.HasIndex; // indexed messages first
        }
        return a.Parsed.HasIndex && a.Parsed.Index < b.Parsed.Index;
      });
    ProblemGroup& group = groups[g];
    group.NumberOfProblems = entries.size();
    const std::size_t shown = std::min(maxPerSource, entries.size());
    for (std::size_t i = 0; i < shown; ++i)
    {
      group.Lines.push_back(*entries[i].Text);
    }
    if (shown < entries.size())
    {
      std::ostringstream os;
      os << "... and " << (entries.size() - shown) << " more problem"
         << (entries.size() - shown == 1 ? "" : "s") << " in " << group.Source;
      // The range of the indices left out (the indexed messages come first).
      if (entries[shown].Parsed.HasIndex)
      {
        std::size_t last = shown;
        while (last + 1 < entries.size() && entries[last + 1].Parsed.HasIndex)
        {
          ++last;
        }
        if (last == shown)
        {
          os << " (light " << entries[shown].Parsed.Index << ")";
        }
        else
        {
          os << " (lights " << entries[shown].Parsed.Index << " to " << entries[last].Parsed.Index
             << ")";
        }
      }
      os << "; " << (entries.size() - shown == 1 ? "that light is" : "those lights are")
         << " skipped too";
      group.Lines.push_back(os.str());
    }
  }
  return groups;
}

/// All lines of SummarizeProblems(), in order (for callers that need no grouping).
inline std::vector<std::string> SummarizeProblemLines(
  const std::vector<std::string>& problems, std::size_t maxPerSource)
{
  std::vector<std::string> lines;
  for (const ProblemGroup& group : SummarizeProblems(problems, maxPerSource))
  {
    lines.insert(lines.end(), group.Lines.begin(), group.Lines.end());
  }
  return lines;
}

} // namespace vtkClusteredLighting

#endif
