// SPDX-License-Identifier: BSD-3-Clause
// vtkClusteredLightSet's value getters and bulk (array) access (issue 14, item 7):
//  - GetPosition(i), GetColor(i), GetAttenuation(i), GetSpotDirection(i) return the same
//    values as the output-argument getters; an index out of range is an error that
//    returns zeros, never a crash;
//  - Get<Parameter>s() fill a vtkDoubleArray with exactly what the per-light getters
//    give, and Set<Parameter>s() of those arrays rebuild an equal set (a round trip),
//    radii included (-1: no explicit radius);
//  - SetPositions() sets the number of lights; other setters need one tuple per light;
//    unsigned char colors are scaled, 4-component colors drop alpha; a null array, wrong
//    components or tuples are errors that change nothing;
//  - IntensityScale: clamped, NaN rejected, applied by GetScaledIntensity() only.
#include "ClusteredLightingTestUtilities.h"

#include "vtkClusteredLightSet.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace
{
int Status = EXIT_SUCCESS;

void Check(bool ok, const std::string& what)
{
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  if (!ok)
  {
    Status = EXIT_FAILURE;
  }
}

bool Same3(const double* a, const double* b)
{
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

// A set of n lights with distinct parameters: every third light a spot, every other
// light with an explicit radius.
void FillRandomSet(vtkClusteredLightSet* set, int n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  set->SetNumberOfLights(n);
  for (int i = 0; i < n; ++i)
  {
    set->SetPosition(i, 10 * U(rng) - 5, 10 * U(rng) - 5, 10 * U(rng) - 5);
    set->SetColor(i, U(rng), U(rng), U(rng));
    set->SetIntensity(i, 2 * U(rng));
    set->SetAttenuation(i, 1.0, U(rng), 10 * U(rng));
    if (i % 2 == 0)
    {
      set->SetRadius(i, 3 * U(rng));
    }
    if (i % 3 == 0)
    {
      set->SetSpot(i, U(rng) - 0.5, U(rng) - 0.5, -1.0, 10 + 60 * U(rng), 1 + 4 * U(rng));
    }
  }
}

// Whether every parameter of every light is equal in both sets (bit for bit).
bool SameLights(vtkClusteredLightSet* a, vtkClusteredLightSet* b, std::string& difference)
{
  if (a->GetNumberOfLights() != b->GetNumberOfLights())
  {
    difference = "number of lights";
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfLights(); ++i)
  {
    double u[3], v[3];
    auto fail = [&](const char* what)
    {
      difference = std::string(what) + " of light " + std::to_string(i);
      return false;
    };
    a->GetPosition(i, u);
    b->GetPosition(i, v);
    if (!Same3(u, v))
    {
      return fail("position");
    }
    a->GetColor(i, u);
    b->GetColor(i, v);
    if (!Same3(u, v))
    {
      return fail("color");
    }
    a->GetAttenuation(i, u);
    b->GetAttenuation(i, v);
    if (!Same3(u, v))
    {
      return fail("attenuation");
    }
    a->GetSpotDirection(i, u);
    b->GetSpotDirection(i, v);
    if (!Same3(u, v))
    {
      return fail("spot direction");
    }
    if (a->GetIntensity(i) != b->GetIntensity(i))
    {
      return fail("intensity");
    }
    if (a->HasRadius(i) != b->HasRadius(i) ||
      (a->HasRadius(i) && a->GetRadius(i) != b->GetRadius(i)))
    {
      return fail("radius");
    }
    if (a->GetConeAngle(i) != b->GetConeAngle(i) || a->GetExponent(i) != b->GetExponent(i))
    {
      return fail("cone angle or exponent");
    }
  }
  return true;
}

void TestValueGetters()
{
  vtkNew<vtkClusteredLightSet> set;
  FillRandomSet(set, 9, 3);
  bool same = true;
  for (vtkIdType i = 0; i < set->GetNumberOfLights(); ++i)
  {
    double v[3];
    set->GetPosition(i, v);
    same = same && Same3(set->GetPosition(i), v);
    set->GetColor(i, v);
    same = same && Same3(set->GetColor(i), v);
    set->GetAttenuation(i, v);
    same = same && Same3(set->GetAttenuation(i), v);
    set->GetSpotDirection(i, v);
    same = same && Same3(set->GetSpotDirection(i), v);
  }
  Check(same, "value getters return what the output-argument getters give");
  const double* p3 = set->GetPosition(3);
  const double* p4 = set->GetPosition(4);
  double v3[3];
  set->GetPosition(3, v3);
  Check(Same3(p3, v3) && !Same3(p3, p4), "two value getters' results stay apart");

  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(set);
  const double* bad = set->GetColor(9);
  const double* negative = set->GetPosition(-1);
  Check(bad && negative && bad[0] == 0 && bad[1] == 0 && bad[2] == 0 &&
      messages->Errors.size() == 2 && messages->Errors[0].find("out of range") != std::string::npos,
    "an index out of range is an error and returns (0, 0, 0)");
}

void TestRoundTrip()
{
  vtkNew<vtkClusteredLightSet> a;
  FillRandomSet(a, 37, 11);
  vtkNew<vtkDoubleArray> positions, colors, intensities, attenuations, radii, directions, cones,
    exponents;
  a->GetPositions(positions);
  a->GetColors(colors);
  a->GetIntensities(intensities);
  a->GetAttenuations(attenuations);
  a->GetRadii(radii);
  a->GetSpotDirections(directions);
  a->GetConeAngles(cones);
  a->GetExponents(exponents);

  // The arrays hold exactly the per-light values.
  bool arrays = positions->GetNumberOfTuples() == 37 && positions->GetNumberOfComponents() == 3 &&
    colors->GetNumberOfComponents() == 3 && intensities->GetNumberOfComponents() == 1 &&
    radii->GetNumberOfTuples() == 37 && exponents->GetNumberOfTuples() == 37;
  for (vtkIdType i = 0; arrays && i < 37; ++i)
  {
    arrays = Same3(positions->GetTuple3(i), a->GetPosition(i)) &&
      Same3(colors->GetTuple3(i), a->GetColor(i)) &&
      Same3(attenuations->GetTuple3(i), a->GetAttenuation(i)) &&
      Same3(directions->GetTuple3(i), a->GetSpotDirection(i)) &&
      intensities->GetValue(i) == a->GetIntensity(i) &&
      radii->GetValue(i) == (a->HasRadius(i) ? a->GetRadius(i) : -1.0) &&
      cones->GetValue(i) == a->GetConeAngle(i) && exponents->GetValue(i) == a->GetExponent(i);
  }
  Check(arrays, "the arrays hold the per-light values, one tuple per light (-1: no radius)");

  vtkNew<vtkClusteredLightSet> b;
  const bool accepted = b->SetPositions(positions) && b->SetColors(colors) &&
    b->SetIntensities(intensities) && b->SetAttenuations(attenuations) && b->SetRadii(radii) &&
    b->SetSpotDirections(directions) && b->SetConeAngles(cones) && b->SetExponents(exponents);
  std::string difference;
  const bool same = SameLights(a, b, difference);
  Check(accepted && same,
    "a set rebuilt from the arrays equals the original" +
      (same ? std::string() : " (differs in " + difference + ")"));

  // The round trip through arrays is exact: a second one changes nothing.
  vtkNew<vtkDoubleArray> again;
  b->GetRadii(again);
  bool radiiSame = again->GetNumberOfTuples() == radii->GetNumberOfTuples();
  for (vtkIdType i = 0; radiiSame && i < again->GetNumberOfTuples(); ++i)
  {
    radiiSame = again->GetValue(i) == radii->GetValue(i);
  }
  Check(radiiSame, "radii round trip, lights without an explicit radius included");

  // SetPositions sets the number of lights; new lights get the defaults.
  vtkNew<vtkFloatArray> more;
  more->SetNumberOfComponents(3);
  more->SetNumberOfTuples(40);
  more->Fill(0.5f);
  const vtkMTimeType before = b->GetMTime();
  Check(b->SetPositions(more) && b->GetNumberOfLights() == 40 && b->GetMTime() > before &&
      b->GetIntensity(39) == 1.0 && !b->HasRadius(39) && b->GetConeAngle(39) == 180.0 &&
      b->GetAttenuation(39)[0] == 1.0 && b->GetPosition(39)[2] == 0.5,
    "SetPositions (a float array) grows the set; new lights get the defaults; MTime grows");
}

void TestConversionsAndErrors()
{
  vtkNew<vtkClusteredLightSet> set;
  set->SetNumberOfLights(2);
  vtkNew<vtkUnsignedCharArray> bytes;
  bytes->SetNumberOfComponents(4);
  bytes->InsertNextTuple4(255, 0, 51, 10);
  bytes->InsertNextTuple4(0, 255, 102, 20);
  Check(set->SetColors(bytes) && std::abs(set->GetColor(0)[0] - 1.0) < 1e-12 &&
      std::abs(set->GetColor(0)[2] - 0.2) < 1e-12 && std::abs(set->GetColor(1)[2] - 0.4) < 1e-12,
    "unsigned char RGBA colors are scaled to [0, 1], alpha dropped");

  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(set);
  vtkNew<vtkDoubleArray> three;
  three->SetNumberOfComponents(3);
  three->SetNumberOfTuples(3);
  three->Fill(7.0);
  vtkNew<vtkDoubleArray> pairs;
  pairs->SetNumberOfComponents(2);
  pairs->SetNumberOfTuples(2);
  pairs->Fill(7.0);
  const double color0[3] = { set->GetColor(0)[0], set->GetColor(0)[1], set->GetColor(0)[2] };
  const vtkMTimeType before = set->GetMTime();
  const bool rejected = !set->SetColors(three) && !set->SetIntensities(pairs) &&
    !set->SetPositions(pairs) && !set->SetRadii(nullptr) && !set->SetColors(pairs);
  Check(rejected && set->GetNumberOfLights() == 2 && Same3(set->GetColor(0), color0) &&
      set->GetMTime() == before,
    "wrong tuples, wrong components and a null array are rejected and change nothing");
  bool named = messages->Errors.size() == 5;
  const char* names[] = { "SetColors(): the array has 3 tuples for 2 lights",
    "SetIntensities(): the vtkDoubleArray has 2 components; it must have 1",
    "SetPositions(): the vtkDoubleArray has 2 components; it must have 3",
    "SetRadii(): the array is null", "it must have 3 or 4" };
  for (int i = 0; named && i < 5; ++i)
  {
    named = messages->Errors[static_cast<std::size_t>(i)].find(names[i]) != std::string::npos;
  }
  Check(named, "each error names the method and what is wrong");

  // Negative radius in SetRadii: no explicit radius.
  vtkNew<vtkDoubleArray> radii;
  radii->InsertNextValue(-1.0);
  radii->InsertNextValue(2.5);
  set->SetRadius(0, 4.0);
  Check(set->SetRadii(radii) && !set->HasRadius(0) && set->HasRadius(1) && set->GetRadius(1) == 2.5,
    "SetRadii: a negative value unsets the radius, others set it");
}

void TestIntensityScale()
{
  vtkNew<vtkClusteredLightSet> set;
  set->AddLight(0, 0, 0);
  set->SetIntensity(0, 0.8);
  Check(set->GetIntensityScale() == 1.0 && set->GetScaledIntensity(0) == 0.8,
    "IntensityScale defaults to 1");
  const vtkMTimeType before = set->GetMTime();
  set->SetIntensityScale(0.25);
  Check(
    set->GetMTime() > before && set->GetScaledIntensity(0) == 0.2 && set->GetIntensity(0) == 0.8,
    "IntensityScale scales GetScaledIntensity only and modifies the set");
  vtkNew<vtkDoubleArray> intensities;
  set->GetIntensities(intensities);
  Check(intensities->GetValue(0) == 0.8, "GetIntensities gives the intensities as set");
  set->SetIntensityScale(-2.0);
  Check(set->GetIntensityScale() == 0.0, "a negative scale is clamped to 0");
  set->SetIntensityScale(1e300);
  Check(set->GetIntensityScale() == static_cast<double>(VTK_FLOAT_MAX),
    "a huge scale is clamped to VTK_FLOAT_MAX");
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(set);
  set->SetIntensityScale(0.5);
  set->SetIntensityScale(std::nan(""));
  Check(set->GetIntensityScale() == 0.5 && messages->Errors.size() == 1,
    "a NaN scale is an error and ignored");
}
} // namespace

int TestClusteredLightSetArrays(int, char*[])
{
  TestValueGetters();
  TestRoundTrip();
  TestConversionsAndErrors();
  TestIntensityScale();
  return Status;
}
