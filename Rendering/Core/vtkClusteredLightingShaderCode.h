// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingShaderCode.h
 * @brief GL-free selection of the optional blocks of the clustered shading sources, a
 *        check of what a mapper's shader does after the lighting, and where declarations
 *        may be inserted into a mapper's shader.
 *
 * The shading sources (Rendering/glsl/vtkClusteredLightingShading{Dec,Impl}.glsl and
 * vtkClusteredLightingDebugImpl.glsl) mark optional code with lines of their own:
 *
 *   //CL_IF(FLAG)      the lines up to the matching //CL_ELSE or //CL_ENDIF are kept
 *                      only when FLAG is set;
 *   //CL_ELSE          the lines up to //CL_ENDIF are kept only when FLAG is not set;
 *   //CL_ENDIF         ends the block.
 *
 *   //CL_TWICE(FLAG)   the lines up to //CL_END_TWICE are emitted twice when FLAG is
 *                      set, each copy in braces that first declare `const int clCopy`
 *                      (0, then 1), and once (clCopy 0) when it is not; the //CL_IF
 *                      blocks inside are selected in each copy. The shader's walk runs
 *                      this way without, then with, the spot lights' code (a constant
 *                      clCopy folds it away; llvmpipe would run a branch's both sides).
 *
 * Blocks nest; a block inside a dropped block is dropped whatever its flag. Leading
 * blanks before a directive are allowed; the directive lines themselves never reach the
 * output. SelectShaderCode() keeps the lines of the set flags, so the text injected into a
 * mapper's shader holds no code path its actor or its lights do not need (GLSL's own
 * #ifdef would leave every path in the text, and in each compiled program's source).
 *
 * An unbalanced source (an //CL_ELSE or //CL_ENDIF without //CL_IF, or an //CL_IF left
 * open at the end) is reported through `error` and selects nothing: a typo in a shader
 * must not silently drop or keep lighting code. Unit-tested in Testing/Unit.
 */
#ifndef vtkClusteredLightingShaderCode_h
#define vtkClusteredLightingShaderCode_h

#include <cctype>  // for std::isalpha, std::isspace
#include <set>     // for std::set
#include <sstream> // for std::istringstream
#include <string>  // for std::string
#include <utility> // for std::pair
#include <vector>  // for std::vector

namespace vtkClusteredLighting
{

namespace Detail
{
/// The source's lines one by one, each with its number and its text without leading
/// blanks (where directives are recognised), and the directives' error messages.
struct ShaderLines
{
  explicit ShaderLines(const std::string& source, std::string* error)
    : In(source)
    , Error(error)
  {
  }
  bool Next()
  {
    if (!std::getline(this->In, this->Line))
    {
      return false;
    }
    ++this->Number;
    const auto first = this->Line.find_first_not_of(" \t");
    this->Trimmed = first == std::string::npos ? std::string() : this->Line.substr(first);
    return true;
  }
  /// Whether the line is `directive`, a flag in parentheses after it: sets `flag`;
  /// `closed` false when the parenthesis is missing.
  bool Is(const char* directive, std::string& flag, bool& closed) const
  {
    const std::string d = directive;
    if (this->Trimmed.rfind(d, 0) != 0)
    {
      return false;
    }
    const auto close = this->Trimmed.find(')');
    closed = close != std::string::npos;
    flag = closed ? this->Trimmed.substr(d.size(), close - d.size()) : std::string();
    return true;
  }
  /// Sets the error (when given) to `what` at this line; returns the empty selection.
  std::string Fail(const std::string& what) const
  {
    if (this->Error)
    {
      *this->Error = what + " at line " + std::to_string(this->Number);
    }
    return std::string();
  }
  std::istringstream In;
  std::string* Error;
  std::string Line, Trimmed;
  int Number = 0;
};
} // namespace Detail

/**
 * Expands the //CL_TWICE(FLAG) ... //CL_END_TWICE blocks of `source` (see the file
 * description). Returns an empty string and sets `error` (when given) if a block is not
 * closed, is nested in another, or an //CL_END_TWICE has no //CL_TWICE.
 */
inline std::string ExpandShaderCopies(
  const std::string& source, const std::set<std::string>& flags, std::string* error = nullptr)
{
  Detail::ShaderLines lines(source, error);
  std::string out, block, flag;
  bool inside = false, twice = false, closed = false;
  while (lines.Next())
  {
    if (lines.Is("//CL_TWICE(", flag, closed))
    {
      if (!closed)
      {
        return lines.Fail("//CL_TWICE without a closing parenthesis");
      }
      if (inside)
      {
        return lines.Fail("//CL_TWICE inside another");
      }
      inside = true;
      twice = flags.count(flag) > 0;
      block.clear();
    }
    else if (lines.Trimmed.rfind("//CL_END_TWICE", 0) == 0)
    {
      if (!inside)
      {
        return lines.Fail("//CL_END_TWICE without //CL_TWICE");
      }
      inside = false;
      for (int copy = 0; copy < (twice ? 2 : 1); ++copy)
      {
        out += "  {\n  const int clCopy = " + std::to_string(copy) + ";\n" + block + "  }\n";
      }
    }
    else
    {
      (inside ? block : out) += lines.Line + '\n';
    }
  }
  if (inside)
  {
    return lines.Fail("//CL_TWICE not closed by the end");
  }
  return out;
}

/**
 * Keeps the lines of `source` whose //CL_IF conditions hold for `flags`, after expanding
 * its //CL_TWICE blocks (ExpandShaderCopies). Returns an empty string and sets `error`
 * (when given) if the directives do not balance.
 */
inline std::string SelectShaderCode(
  const std::string& source, const std::set<std::string>& flags, std::string* error = nullptr)
{
  std::string copyError;
  const std::string expanded = ExpandShaderCopies(source, flags, &copyError);
  if (!copyError.empty())
  {
    if (error)
    {
      *error = copyError;
    }
    return std::string();
  }
  Detail::ShaderLines lines(expanded, error);
  std::string out, flag;
  bool closed = false;
  // One entry per open block: (its condition, whether its lines are emitted).
  std::vector<std::pair<bool, bool>> open;
  auto emitting = [&open]() { return open.empty() || open.back().second; };
  while (lines.Next())
  {
    const std::string& trimmed = lines.Trimmed;
    if (lines.Is("//CL_IF(", flag, closed))
    {
      if (!closed)
      {
        return lines.Fail("//CL_IF without a closing parenthesis");
      }
      const bool condition = flags.count(flag) > 0;
      const bool parent = emitting();
      open.emplace_back(condition, parent && condition);
    }
    else if (trimmed.rfind("//CL_ELSE", 0) == 0)
    {
      if (open.empty())
      {
        return lines.Fail("//CL_ELSE without //CL_IF");
      }
      const bool condition = !open.back().first;
      open.pop_back();
      const bool parent = emitting();
      open.emplace_back(condition, parent && condition);
    }
    else if (trimmed.rfind("//CL_ENDIF", 0) == 0)
    {
      if (open.empty())
      {
        return lines.Fail("//CL_ENDIF without //CL_IF");
      }
      open.pop_back();
    }
    else if (emitting())
    {
      out += lines.Line;
      out += '\n';
    }
  }
  if (!open.empty())
  {
    return lines.Fail("//CL_IF not closed by the end");
  }
  if (error)
  {
    error->clear();
  }
  return out;
}

/// Replaces every occurrence of `key` in `code` with `value`.
inline void ReplaceShaderKey(std::string& code, const std::string& key, const std::string& value)
{
  if (key.empty())
  {
    return;
  }
  for (auto pos = code.find(key); pos != std::string::npos; pos = code.find(key, pos))
  {
    code.replace(pos, key.size(), value);
    pos += value.size();
  }
}

/**
 * True if `source` assigns to the fragment's colour output (gl_FragData[0], whole or a
 * swizzle, with = or an arithmetic assignment) anywhere at or after offset `from`, or if
 * `from` is npos (the position is unknown). Reads are not assignments: VTK's alpha test
 * "gl_FragData[0].a <= 0.0" does not count, its texture modulation
 * "gl_FragData[0] = gl_FragData[0] * tcolor" does. The pass stops a fragment's light walk
 * at saturation only where nothing after the lighting rescales the colour.
 */
inline bool WritesColorAfter(const std::string& source, std::size_t from)
{
  if (from == std::string::npos)
  {
    return true;
  }
  const std::string output = "gl_FragData[0]";
  for (std::size_t at = source.find(output, from); at != std::string::npos;
       at = source.find(output, at + output.size()))
  {
    std::size_t i = at + output.size();
    if (i < source.size() && source[i] == '.')
    {
      ++i;
      while (i < source.size() && std::isalpha(static_cast<unsigned char>(source[i])))
      {
        ++i; // the swizzle
      }
    }
    while (i < source.size() && std::isspace(static_cast<unsigned char>(source[i])))
    {
      ++i;
    }
    if (i + 1 < source.size() &&
      ((source[i] == '=' && source[i + 1] != '=') ||
        (std::string("+-*/").find(source[i]) != std::string::npos && source[i + 1] == '=')))
    {
      return true;
    }
  }
  return false;
}

/**
 * Inserts `text` (declarations, or #extension directives) where a shader of VTK's may take
 * it: after the line of the source's last #extension directive (GLSL allows nothing but
 * directives before one: VTK's GPU volume ray caster declares its own in its text, and a
 * declaration put above it failed to compile, so volumes vanished under the pass), else
 * right after VTK's //VTK::System::Dec tag. Returns false, and leaves the source alone,
 * when it has neither.
 */
inline bool InsertDeclarations(std::string& source, const std::string& text)
{
  std::size_t at = std::string::npos;
  for (std::size_t line = 0; line < source.size();)
  {
    std::size_t end = source.find('\n', line);
    end = end == std::string::npos ? source.size() : end;
    std::size_t first = line;
    while (first < end && (source[first] == ' ' || source[first] == '\t'))
    {
      ++first;
    }
    if (source.compare(first, 10, "#extension") == 0)
    {
      at = end;
    }
    line = end + 1;
  }
  if (at == std::string::npos)
  {
    const std::string tag = "//VTK::System::Dec";
    const std::size_t tagAt = source.find(tag);
    if (tagAt == std::string::npos)
    {
      return false;
    }
    at = tagAt + tag.size();
  }
  source.insert(at, "\n" + text);
  return true;
}

} // namespace vtkClusteredLighting

#endif
