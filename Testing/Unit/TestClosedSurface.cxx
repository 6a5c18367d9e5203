// SPDX-License-Identifier: BSD-3-Clause
// When the pass may cull a surface's back faces (vtkClusteredLightingClosedSurface.h):
// closed, consistently oriented meshes are told from open, inconsistent and hollow ones;
// a box is beyond the near plane only when no corner is at or before it; and the face
// chosen for culling keeps, in window coordinates, exactly the faces that face the eye,
// for perspective and parallel cameras, mirrored models and inward meshes.
#include "vtkClusteredLightingClosedSurface.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace vtkClusteredLighting;

namespace
{
/// Polygons over points, in VTK 9's cell array layout.
struct Mesh
{
  std::vector<double> Points;
  std::vector<std::int64_t> Offsets{ 0 };
  std::vector<std::int64_t> Connectivity;

  std::int64_t AddPoint(const glm::dvec3& p)
  {
    this->Points.insert(this->Points.end(), { p.x, p.y, p.z });
    return static_cast<std::int64_t>(this->Points.size() / 3 - 1);
  }
  void AddPolygon(std::vector<std::int64_t> ids)
  {
    this->Connectivity.insert(this->Connectivity.end(), ids.begin(), ids.end());
    this->Offsets.push_back(static_cast<std::int64_t>(this->Connectivity.size()));
  }
  std::int64_t NumberOfPolygons() const
  {
    return static_cast<std::int64_t>(this->Offsets.size()) - 1;
  }
  glm::dvec3 Point(std::int64_t id) const
  {
    return { this->Points[3 * id], this->Points[3 * id + 1], this->Points[3 * id + 2] };
  }
  void Reverse()
  {
    for (std::int64_t c = 0; c < this->NumberOfPolygons(); ++c)
    {
      std::reverse(this->Connectivity.begin() + this->Offsets[c],
        this->Connectivity.begin() + this->Offsets[c + 1]);
    }
  }
  void Append(const Mesh& other)
  {
    const std::int64_t base = static_cast<std::int64_t>(this->Points.size() / 3);
    this->Points.insert(this->Points.end(), other.Points.begin(), other.Points.end());
    for (std::int64_t c = 0; c < other.NumberOfPolygons(); ++c)
    {
      std::vector<std::int64_t> ids;
      for (std::int64_t k = other.Offsets[c]; k < other.Offsets[c + 1]; ++k)
      {
        ids.push_back(other.Connectivity[k] + base);
      }
      this->AddPolygon(ids);
    }
  }
  SurfaceClosure Closure() const
  {
    return ComputeSurfaceClosure(this->Points.data(),
      static_cast<std::int64_t>(this->Points.size() / 3), this->Offsets.data(),
      this->Connectivity.data(), this->NumberOfPolygons());
  }
};

/// A cube of quads with outward normals; `splitFaces` gives each face its own 4 points
/// (as a mesh whose normals were split at its edges).
Mesh Cube(const glm::dvec3& lo, double size, bool splitFaces = false, int skipFace = -1)
{
  // The faces' corners (bit 0: x, bit 1: y, bit 2: z), counter-clockwise from outside.
  const int faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  Mesh m;
  auto corner = [&](int c) { return lo + size * glm::dvec3(c & 1, (c >> 1) & 1, (c >> 2) & 1); };
  std::int64_t shared[8];
  for (int c = 0; c < 8 && !splitFaces; ++c)
  {
    shared[c] = m.AddPoint(corner(c));
  }
  for (int f = 0; f < 6; ++f)
  {
    if (f == skipFace)
    {
      continue;
    }
    std::vector<std::int64_t> ids;
    for (int k = 0; k < 4; ++k)
    {
      ids.push_back(splitFaces ? m.AddPoint(corner(faces[f][k])) : shared[faces[f][k]]);
    }
    m.AddPolygon(ids);
  }
  return m;
}

/// A latitude-longitude sphere of triangles (outward), as vtkSphereSource builds one,
/// optionally with the seam's points repeated (as texture coordinates need).
Mesh Sphere(const glm::dvec3& centre, double radius, int theta, int phi, bool seam = false)
{
  const double pi = 3.14159265358979323846;
  Mesh m;
  const std::int64_t north = m.AddPoint(centre + glm::dvec3(0, 0, radius));
  const std::int64_t south = m.AddPoint(centre - glm::dvec3(0, 0, radius));
  const int columns = seam ? theta + 1 : theta;
  std::vector<std::int64_t> ring(static_cast<std::size_t>(columns * (phi - 1)));
  for (int j = 1; j < phi; ++j)
  {
    for (int i = 0; i < columns; ++i)
    {
      const double t = 2.0 * pi * (i % theta) / theta, p = pi * j / phi;
      ring[static_cast<std::size_t>((j - 1) * columns + i)] = m.AddPoint(centre +
        radius * glm::dvec3(std::sin(p) * std::cos(t), std::sin(p) * std::sin(t), std::cos(p)));
    }
  }
  auto at = [&](int j, int i)
  {
    const int column = seam ? i : i % theta;
    return ring[static_cast<std::size_t>((j - 1) * columns + column)];
  };
  for (int i = 0; i < theta; ++i)
  {
    m.AddPolygon({ north, at(1, i), at(1, i + 1) });
    m.AddPolygon({ south, at(phi - 1, i + 1), at(phi - 1, i) });
    for (int j = 1; j + 1 < phi; ++j)
    {
      m.AddPolygon({ at(j, i), at(j + 1, i), at(j + 1, i + 1) });
      m.AddPolygon({ at(j, i), at(j + 1, i + 1), at(j, i + 1) });
    }
  }
  return m;
}

/// Twice the signed area of the triangle's projection in normalized device coordinates
/// (positive: counter-clockwise, GL's front face).
double WindowArea(
  const glm::dmat4& clipFromModel, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
  auto ndc = [&](const glm::dvec3& p)
  {
    const glm::dvec4 q = clipFromModel * glm::dvec4(p, 1.0);
    return glm::dvec2(q) / q.w;
  };
  const glm::dvec2 pa = ndc(a), pb = ndc(b), pc = ndc(c);
  return (pb.x - pa.x) * (pc.y - pa.y) - (pb.y - pa.y) * (pc.x - pa.x);
}
}

TEST(ClosedSurface, ACubeOfSharedOrSplitPointsIsClosedAndFacesOut)
{
  for (bool split : { false, true })
  {
    Mesh cube = Cube(glm::dvec3(-1.0), 2.0, split);
    SurfaceClosure c = cube.Closure();
    EXPECT_TRUE(c.Closed) << c.Reason;
    EXPECT_EQ(c.Orientation, 1);
    cube.Reverse();
    c = cube.Closure();
    EXPECT_TRUE(c.Closed) << c.Reason;
    EXPECT_EQ(c.Orientation, -1);
  }
}

TEST(ClosedSurface, SpheresAreClosedWithOrWithoutASeamAtEveryScale)
{
  for (double scale : { 1e-3, 1.0, 1e6 })
  {
    for (bool seam : { false, true })
    {
      const Mesh sphere = Sphere(glm::dvec3(3.0, -2.0, 5.0) * scale, 0.5 * scale, 24, 12, seam);
      const SurfaceClosure c = sphere.Closure();
      EXPECT_TRUE(c.Closed) << c.Reason << " at scale " << scale;
      EXPECT_EQ(c.Orientation, 1) << "at scale " << scale;
    }
  }
  // A small sphere far from the origin (its coordinates' rounding against its size).
  const SurfaceClosure far = Sphere(glm::dvec3(1e6, 1e6, -1e6), 1e-2, 16, 8).Closure();
  EXPECT_TRUE(far.Closed);
  EXPECT_EQ(far.Orientation, 1);
}

TEST(ClosedSurface, OpenInconsistentAndNonManifoldMeshesAreNotClosed)
{
  SurfaceClosure c = Cube(glm::dvec3(0.0), 1.0, false, 2).Closure();
  EXPECT_FALSE(c.Closed);
  EXPECT_STREQ(c.Reason, "an edge bounds only one polygon");
  EXPECT_EQ(c.Orientation, 0);

  Mesh flipped = Cube(glm::dvec3(0.0), 1.0);
  std::reverse(flipped.Connectivity.begin(), flipped.Connectivity.begin() + 4);
  c = flipped.Closure();
  EXPECT_FALSE(c.Closed);
  EXPECT_STREQ(c.Reason, "two polygons run along an edge the same way");

  // A third polygon on one of the cube's edges (a fin).
  Mesh fin = Cube(glm::dvec3(0.0), 1.0);
  const std::int64_t f0 = fin.AddPoint(glm::dvec3(-1.0, -1.0, 0.0));
  const std::int64_t f1 = fin.AddPoint(glm::dvec3(-1.0, -1.0, 1.0));
  fin.AddPolygon({ 0, 4, f1, f0 }); // corners 0 (0,0,0) and 4 (0,0,1)
  EXPECT_FALSE(fin.Closure().Closed);

  Mesh repeated = Cube(glm::dvec3(0.0), 1.0);
  repeated.AddPolygon({ 0, 1, 0 });
  c = repeated.Closure();
  EXPECT_FALSE(c.Closed);
  EXPECT_STREQ(c.Reason, "a polygon repeats a vertex");

  Mesh nan = Cube(glm::dvec3(0.0), 1.0);
  nan.Points[4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(nan.Closure().Closed);

  Mesh line = Cube(glm::dvec3(0.0), 1.0);
  line.AddPolygon({ 0, 1 });
  EXPECT_FALSE(line.Closure().Closed);

  EXPECT_FALSE(Mesh().Closure().Closed);
}

TEST(ClosedSurface, EveryComponentMustFaceTheSameWay)
{
  // Two separate outward cubes, and a cube inside another (both outward): one way.
  Mesh two = Cube(glm::dvec3(0.0), 1.0);
  two.Append(Cube(glm::dvec3(3.0), 1.0));
  EXPECT_EQ(two.Closure().Orientation, 1);
  Mesh nested = Cube(glm::dvec3(0.0), 4.0);
  nested.Append(Sphere(glm::dvec3(2.0), 1.0, 16, 8));
  EXPECT_EQ(nested.Closure().Orientation, 1);

  // One of two cubes inward: closed, but a back face of it would be seen first.
  Mesh mixed = Cube(glm::dvec3(0.0), 1.0);
  Mesh inward = Cube(glm::dvec3(3.0), 0.5);
  inward.Reverse();
  mixed.Append(inward);
  SurfaceClosure c = mixed.Closure();
  EXPECT_TRUE(c.Closed);
  EXPECT_EQ(c.Orientation, 0);

  // A hollow shell (its cavity faces inward): sound, but not one orientation.
  Mesh shell = Cube(glm::dvec3(0.0), 4.0);
  Mesh cavity = Sphere(glm::dvec3(2.0), 1.0, 16, 8);
  cavity.Reverse();
  shell.Append(cavity);
  EXPECT_EQ(shell.Closure().Orientation, 0);

  // A flat closed surface: a quad and its reverse.
  Mesh flat;
  for (const glm::dvec3& p :
    { glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(1, 1, 0), glm::dvec3(0, 1, 0) })
  {
    flat.AddPoint(p);
  }
  flat.AddPolygon({ 0, 1, 2, 3 });
  flat.AddPolygon({ 3, 2, 1, 0 });
  c = flat.Closure();
  EXPECT_TRUE(c.Closed);
  EXPECT_EQ(c.Orientation, 0);
}

TEST(ClosedSurface, ABoxIsBeyondTheNearPlaneOnlyWhenEveryCornerIs)
{
  const glm::dmat4 view =
    glm::lookAt(glm::dvec3(0.0, 0.0, 10.0), glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
  for (const glm::dmat4& projection :
    { glm::perspective(0.5, 1.3, 1.0, 100.0), glm::ortho(-4.0, 4.0, -3.0, 3.0, 1.0, 100.0) })
  {
    const glm::dmat4 clip = projection * view;
    const double inFront[6] = { -1, 1, -1, 1, -1, 1 };
    EXPECT_TRUE(IsBoxBeyondNearPlane(clip, inFront));
    // Off to the side (outside the frustum) but beyond the near plane: still true.
    const double aside[6] = { 50, 51, -1, 1, -1, 1 };
    EXPECT_TRUE(IsBoxBeyondNearPlane(clip, aside));
    // Around the eye; straddling the near plane (z = 9); behind the eye; empty.
    const double aroundEye[6] = { -1, 1, -1, 1, 8, 12 };
    const double straddling[6] = { -1, 1, -1, 1, 8.5, 9.5 };
    const double justBeyond[6] = { -1, 1, -1, 1, 8.5, 8.99 };
    const double behind[6] = { -1, 1, -1, 1, 11, 12 };
    const double empty[6] = { 1, -1, 0, 0, 0, 0 };
    EXPECT_FALSE(IsBoxBeyondNearPlane(clip, aroundEye));
    EXPECT_FALSE(IsBoxBeyondNearPlane(clip, straddling));
    EXPECT_TRUE(IsBoxBeyondNearPlane(clip, justBeyond));
    EXPECT_FALSE(IsBoxBeyondNearPlane(clip, behind));
    EXPECT_FALSE(IsBoxBeyondNearPlane(clip, empty));
  }
}

// The rule behind ChooseCulledFace, checked where it acts: project every triangle of a
// sphere seen from outside, and the face the rule culls must be exactly the triangles
// that face away from the eye (perspective and parallel cameras, mirrored and scaled
// models, outward and inward spheres).
TEST(ClosedSurface, TheCulledFaceIsTheOneFacingAwayFromTheEye)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 64; ++trial)
  {
    const glm::dvec3 eye = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng))) * 6.0;
    const glm::dmat4 view = glm::lookAt(eye, glm::dvec3(0.0), glm::dvec3(0.3, 1.0, 0.1));
    const bool parallel = trial % 2 == 1;
    const glm::dmat4 projection = parallel ? glm::ortho(-2.0, 2.0, -1.5, 1.5, 0.5, 20.0)
                                           : glm::perspective(0.8, 1.3, 0.5, 20.0);
    const glm::dvec3 mirror((trial / 2) % 2 ? -1.0 : 1.0, (trial / 4) % 2 ? -1.5 : 1.0, 1.0);
    const glm::dmat4 model = glm::scale(glm::dmat4(1.0), mirror);
    const bool inward = (trial / 8) % 2 == 1;
    Mesh sphere = Sphere(glm::dvec3(0.0), 1.0, 12, 6);
    if (inward)
    {
      sphere.Reverse();
    }
    const SurfaceClosure closure = sphere.Closure();
    ASSERT_TRUE(closure.Closed);
    ASSERT_EQ(closure.Orientation, inward ? -1 : 1);
    const glm::dmat4 clip = projection * view * model;
    const int culled = ChooseCulledFace(closure.Orientation, glm::determinant(clip));
    ASSERT_NE(culled, 0);
    const glm::dvec3 eyeInModel = glm::dvec3(glm::inverse(view * model)[3]);
    const glm::dvec3 forwardInModel =
      glm::normalize(glm::dvec3(glm::inverse(view * model) * glm::dvec4(0, 0, -1, 0)));
    for (std::int64_t c = 0; c < sphere.NumberOfPolygons(); ++c)
    {
      const glm::dvec3 a = sphere.Point(sphere.Connectivity[sphere.Offsets[c]]);
      const glm::dvec3 b = sphere.Point(sphere.Connectivity[sphere.Offsets[c] + 1]);
      const glm::dvec3 d = sphere.Point(sphere.Connectivity[sphere.Offsets[c] + 2]);
      // Outward normal of the solid (the polygon's normal, turned for an inward mesh).
      const glm::dvec3 n = glm::cross(b - a, d - a) * (inward ? -1.0 : 1.0);
      const glm::dvec3 toEye = parallel ? -forwardInModel : eyeInModel - a;
      const double facing = glm::dot(n, toEye);
      const double area = WindowArea(clip, a, b, d);
      if (std::abs(facing) < 1e-9 || std::abs(area) < 1e-12)
      {
        continue; // seen edge-on
      }
      // GL culls GL_BACK where the window area is negative, GL_FRONT where positive.
      const bool removed = culled > 0 ? area < 0.0 : area > 0.0;
      EXPECT_EQ(removed, facing < 0.0) << "trial " << trial << " polygon " << c;
      ++checked;
    }
  }
  EXPECT_GT(checked, 64 * 50);
}

TEST(ClosedSurface, NoFaceIsCulledWithoutAnOrientationOrAVolume)
{
  EXPECT_EQ(ChooseCulledFace(0, -1.0), 0);
  EXPECT_EQ(ChooseCulledFace(1, 0.0), 0);
  EXPECT_EQ(ChooseCulledFace(1, std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(ChooseCulledFace(1, -2.0), 1);
  EXPECT_EQ(ChooseCulledFace(-1, -2.0), -1);
  EXPECT_EQ(ChooseCulledFace(1, 2.0), -1);
}
