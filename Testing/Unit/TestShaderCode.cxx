// SPDX-License-Identifier: BSD-3-Clause
// The //CL_IF preprocessor that keeps only the code paths a shader variant needs.
#include "vtkClusteredLightingShaderCode.h"

#include <gtest/gtest.h>

using namespace vtkClusteredLighting;

namespace
{
const char* Source = "a\n"
                     "//CL_IF(X)\n"
                     "x\n"
                     "  //CL_IF(Y)\n"
                     "xy\n"
                     "  //CL_ELSE\n"
                     "x-not-y\n"
                     "  //CL_ENDIF\n"
                     "//CL_ELSE\n"
                     "not-x\n"
                     "//CL_IF(Y)\n"
                     "not-x-but-y\n"
                     "//CL_ENDIF\n"
                     "//CL_ENDIF\n"
                     "b\n";
}

TEST(ShaderCode, KeepsOnlyTheBlocksOfTheSetFlags)
{
  EXPECT_EQ(SelectShaderCode(Source, {}), "a\nnot-x\nb\n");
  EXPECT_EQ(SelectShaderCode(Source, { "X" }), "a\nx\nx-not-y\nb\n");
  EXPECT_EQ(SelectShaderCode(Source, { "Y" }), "a\nnot-x\nnot-x-but-y\nb\n");
  EXPECT_EQ(SelectShaderCode(Source, { "X", "Y" }), "a\nx\nxy\nb\n");
}

TEST(ShaderCode, UnknownFlagsAndPlainTextPassThrough)
{
  EXPECT_EQ(SelectShaderCode("plain\n  indented\n", { "Z" }), "plain\n  indented\n");
  // A flag name must match exactly: X is not XY.
  EXPECT_EQ(SelectShaderCode("//CL_IF(XY)\nk\n//CL_ENDIF\n", { "X" }), "");
  // Directive lines never reach the output, whatever their indentation.
  const std::string out = SelectShaderCode(Source, { "X", "Y" });
  EXPECT_EQ(out.find("CL_"), std::string::npos);
}

TEST(ShaderCode, UnbalancedDirectivesAreErrorsNotSilentSelections)
{
  std::string error;
  EXPECT_EQ(SelectShaderCode("//CL_IF(X)\nx\n", { "X" }, &error), "");
  EXPECT_NE(error.find("not closed"), std::string::npos) << error;
  EXPECT_EQ(SelectShaderCode("x\n//CL_ENDIF\n", {}, &error), "");
  EXPECT_NE(error.find("//CL_ENDIF without //CL_IF"), std::string::npos) << error;
  EXPECT_EQ(SelectShaderCode("//CL_ELSE\n", {}, &error), "");
  EXPECT_NE(error.find("//CL_ELSE without //CL_IF"), std::string::npos) << error;
  EXPECT_EQ(SelectShaderCode("//CL_IF(X\n//CL_ENDIF\n", {}, &error), "");
  EXPECT_NE(error.find("parenthesis"), std::string::npos) << error;
  EXPECT_EQ(SelectShaderCode(Source, { "X" }, &error), "a\nx\nx-not-y\nb\n");
  EXPECT_TRUE(error.empty()) << error;
}

// //CL_TWICE(FLAG): two copies in braces (clCopy 0 and 1) when FLAG is set, one (clCopy 0)
// when not; the //CL_IF blocks inside are selected in each copy; malformed blocks select
// nothing and say why.
TEST(ShaderCode, TwiceBlocksRepeatWhenTheirFlagIsSet)
{
  const std::string source = "a\n"
                             "//CL_TWICE(S)\n"
                             "w\n"
                             "//CL_IF(S)\n"
                             "s\n"
                             "//CL_ENDIF\n"
                             "//CL_END_TWICE\n"
                             "b\n";
  EXPECT_EQ(SelectShaderCode(source, {}), "a\n  {\n  const int clCopy = 0;\nw\n  }\nb\n");
  EXPECT_EQ(SelectShaderCode(source, { "S" }),
    "a\n  {\n  const int clCopy = 0;\nw\ns\n  }\n  {\n  const int clCopy = 1;\nw\ns\n  }\nb\n");
  std::string error;
  for (const char* bad : { "//CL_TWICE(S)\nw\n", "//CL_END_TWICE\n",
         "//CL_TWICE(S)\n//CL_TWICE(T)\n//CL_END_TWICE\n//CL_END_TWICE\n", "//CL_TWICE(S\n" })
  {
    EXPECT_EQ(SelectShaderCode(bad, { "S" }, &error), "") << bad;
    EXPECT_NE(error.find("CL_"), std::string::npos) << bad;
    error.clear();
  }
  // A //CL_IF left open inside a copy is still an error.
  EXPECT_EQ(SelectShaderCode("//CL_TWICE(S)\n//CL_IF(S)\n//CL_END_TWICE\n", { "S" }, &error), "");
  EXPECT_FALSE(error.empty());
}

TEST(ShaderCode, ReplaceShaderKeyReplacesEveryOccurrence)
{
  std::string code = "const int n = @N@; int m = @N@ + @M@;";
  ReplaceShaderKey(code, "@N@", "12");
  ReplaceShaderKey(code, "@M@", "@M@@M@"); // a value containing the key is not re-expanded
  EXPECT_EQ(code, "const int n = 12; int m = 12 + @M@@M@;");
}

TEST(ShaderCode, WritesColorAfterFindsAssignmentsNotReads)
{
  // VTK 9.1's fragment template after the lighting, as the pass sees it.
  const std::string lighting = "  gl_FragData[0] = vec4(ambientColor + diffuse, opacity);\n"
                               "  //VTK::ClusteredLight::Impl\n";
  const std::string alphaTest = "  if (gl_FragData[0].a <= 0.0)\n    {\n    discard;\n    }\n";
  const std::string plain = lighting + alphaTest + "  //VTK::DepthPeeling::Impl\n";
  const std::size_t from = plain.find("//VTK::ClusteredLight::Impl");
  EXPECT_FALSE(WritesColorAfter(plain, from)); // the write before `from` does not count
  EXPECT_TRUE(WritesColorAfter(plain, 0));
  // VTK's texture modulation, and other ways of writing the colour.
  const std::string textured = lighting +
    "if (gl_FrontFacing == true || showTexturesOnBackface) {gl_FragData[0] = gl_FragData[0] * "
    "tcolor; }\n" +
    alphaTest;
  EXPECT_TRUE(WritesColorAfter(textured, from));
  for (const char* write : { "gl_FragData[0]*=t;", "gl_FragData[0].rgb /= 2.0;",
         "gl_FragData[0].xyz+=c;", "gl_FragData[0] -= c;", "gl_FragData[0].r=1.0;" })
  {
    EXPECT_TRUE(WritesColorAfter(lighting + write, from)) << write;
  }
  for (const char* read : { "if (gl_FragData[0].a == 0.0) discard;", "x = gl_FragData[0];",
         "b = gl_FragData[0].rgb >= vec3(1.0);", "c = gl_FragData[1];" })
  {
    EXPECT_FALSE(WritesColorAfter(lighting + read, from)) << read;
  }
  EXPECT_TRUE(WritesColorAfter(plain, std::string::npos)); // unknown position: assume so
}

TEST(ShaderCode, InsertDeclarationsGoesAfterTheLastExtensionDirective)
{
  // VTK 9.1's polydata vertex template: after the System tag.
  std::string polydata = "//VTK::System::Dec\n\nin vec4 vertexMC;\nvoid main() {}\n";
  EXPECT_TRUE(InsertDeclarations(polydata, "invariant gl_Position;\n"));
  EXPECT_EQ(polydata,
    "//VTK::System::Dec\ninvariant gl_Position;\n\n\nin vec4 vertexMC;\nvoid main() {}\n");

  // VTK 9.1's GPU volume ray caster (raycastervs.glsl) declares an extension of its own in
  // its text: a declaration above it is a compile error ("#extension directive is not
  // allowed in the middle of a shader"), so it goes after it (and after indented ones).
  const std::string head = "//VTK::System::Dec\n/// Needed to enable inverse function\n"
                           "#extension GL_ARB_gpu_shader5 : enable\n";
  const std::string body = "in vec3 in_vertexPos;\nvoid main() {}\n";
  std::string volume = head + "  #extension GL_ARB_other : enable\n" + body;
  EXPECT_TRUE(InsertDeclarations(volume, "invariant gl_Position;\n"));
  EXPECT_EQ(volume, head + "  #extension GL_ARB_other : enable\ninvariant gl_Position;\n\n" + body);
  // A comment that mentions the word is not a directive.
  std::string mentioned = head + "// see #extension above\n" + body;
  EXPECT_TRUE(InsertDeclarations(mentioned, "X\n"));
  EXPECT_EQ(mentioned.find("X\n"), head.size());

  // Neither a tag nor a directive: left alone.
  std::string bare = "void main() {}\n";
  EXPECT_FALSE(InsertDeclarations(bare, "X\n"));
  EXPECT_EQ(bare, "void main() {}\n");
}
