// SPDX-License-Identifier: BSD-3-Clause
// Spot lights assigned by their cones (vtkClusteredLightingSpotBounds.h): the sector's
// sphere and the cone-ball test hold every point the light can reach, the list shader's
// float test passes wherever the double one does, and the reference and the CPU's quads
// keep every cluster a spot light reaches while cutting the ones outside its cone.
#include "TestUtilities.h"
#include "vtkClusteredLightingAssignment.h"
#include "vtkClusteredLightingReference.h"
#include "vtkClusteredLightingSpotBounds.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <set>

using namespace vtkClusteredLighting;

namespace
{
const double Degree = 3.14159265358979323846 / 180.0;

glm::dvec3 RandomUnit(std::mt19937& rng)
{
  std::normal_distribution<double> n(0.0, 1.0);
  for (;;)
  {
    const glm::dvec3 v(n(rng), n(rng), n(rng));
    const double len = glm::length(v);
    if (len > 1e-6)
    {
      return v / len;
    }
  }
}

/// The point at distance d from apex, angle phi from axis, azimuth psi.
glm::dvec3 ConePoint(
  const glm::dvec3& apex, const glm::dvec3& axis, double d, double phi, double psi)
{
  const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(axis, helper));
  const glm::dvec3 w = glm::cross(axis, u);
  return apex +
    d * (std::cos(phi) * axis + std::sin(phi) * (std::cos(psi) * u + std::sin(psi) * w));
}

const double Cones[] = { 0.0, 0.05, 1.0, 10.0, 30.0, 44.9, 45.0, 45.1, 60.0, 80.0, 89.8, 89.9 };

/// The list shader's clSpotConeMayReach (vtkClusteredLightingListFS.glsl), in float.
bool ShaderConeTest(
  const glm::vec3& apex, const glm::vec3& axis, float cosCone, const glm::vec3& centre, float rho)
{
  const glm::vec3 v = centre - apex;
  const float along = glm::dot(v, axis);
  const float across = std::sqrt(std::max(glm::dot(v, v) - along * along, 0.0f));
  const float sinCone = std::sqrt(std::max(1.0f - cosCone * cosCone, 0.0f));
  const float slack = rho + static_cast<float>(SpotConeShaderSlack) * glm::length(v);
  return cosCone * across - sinCone * along <= slack && along >= -slack;
}
}

// Every point within the radius and the widened cone lies in the sector's sphere, at
// every scale; the sphere is the smaller one the header promises.
TEST(SpotBounds, SectorSphereHoldsTheWidenedSector)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (const double scale : { 1e-3, 1.0, 1e6 })
  {
    for (const double cone : Cones)
    {
      const glm::dvec3 apex = scale * glm::dvec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
      const glm::dvec3 axis = RandomUnit(rng);
      const double r = scale * (0.5 + U(rng));
      const double cosCone = std::cos(cone * Degree);
      const SpotSectorSphere s = ComputeSpotSectorSphere(apex, axis, cosCone, r);
      const double widest = cone * Degree + 0.95 * SpotConeSlack;
      double worst = 0.0;
      for (int k = 0; k < 4000; ++k)
      {
        // Half the samples on the cap's rim and the cone's edge, where the sphere is tight.
        const double d =
          k % 2 ? r * (s.Radius < r ? 1.0 + 5e-6 : 1.0 - 1e-12) : r * std::cbrt(U(rng));
        const double phi = k % 4 < 2 ? widest : widest * U(rng);
        const glm::dvec3 p = ConePoint(apex, axis, d, phi, 6.283185307179586 * U(rng));
        worst = std::max(worst, glm::length(p - s.Centre) / s.Radius);
      }
      EXPECT_LE(worst, 1.0) << "cone " << cone << " scale " << scale;
      // The apex too.
      EXPECT_LE(glm::length(apex - s.Centre), s.Radius) << "cone " << cone;
      const double expected = cone <= 44.9
        ? 1.0 / (2.0 * std::cos(cone * Degree))
        : std::sin(std::min(cone * Degree + SpotConeSlack, 1.5707963));
      EXPECT_NEAR(s.Radius / r, expected, 3e-3) << "cone " << cone;
    }
  }
  // 30 degrees (VTK's default cone): 0.577 of the radius.
  const SpotSectorSphere s =
    ComputeSpotSectorSphere(glm::dvec3(0.0), glm::dvec3(0, 0, -1), std::cos(30.0 * Degree), 1.0);
  EXPECT_LT(s.Radius, 0.58);
  // 90 degrees or more once widened: the light's own sphere.
  const SpotSectorSphere wide =
    ComputeSpotSectorSphere(glm::dvec3(1.0), glm::dvec3(0, 0, -1), std::cos(89.95 * Degree), 2.0);
  EXPECT_EQ(wide.Radius, 2.0);
  EXPECT_EQ(wide.Centre, glm::dvec3(1.0));
}

// A ball holding a point of the widened cone always passes; balls wholly outside it are
// rejected (the test is not vacuous), and a ball holding the apex passes whatever its side.
TEST(SpotBounds, ConeBallTestKeepsEveryBallThatHoldsAPointOfTheCone)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int rejected = 0, outside = 0;
  for (const double scale : { 1e-3, 1.0, 1e6 })
  {
    for (const double cone : Cones)
    {
      const glm::dvec3 apex = scale * glm::dvec3(U(rng), U(rng), U(rng));
      const glm::dvec3 axis = RandomUnit(rng);
      const double cosCone = std::cos(cone * Degree);
      const double widest = cone * Degree + 0.95 * SpotConeSlack;
      for (int k = 0; k < 3000; ++k)
      {
        const double d = scale * 4.0 * U(rng);
        const glm::dvec3 p =
          ConePoint(apex, axis, d, widest * (k % 3 ? 1.0 : U(rng)), 6.283185307179586 * U(rng));
        const double rho = scale * 2.0 * U(rng) * U(rng);
        const glm::dvec3 centre = p + rho * U(rng) * RandomUnit(rng);
        ASSERT_TRUE(SpotConeMayReachBall(apex, axis, cosCone, centre, rho))
          << "cone " << cone << " scale " << scale << " sample " << k;
        // A ball whose nearest direction is 0.01 radians past the widened cone.
        const double D = scale * (0.1 + 4.0 * U(rng));
        const double small = D * 0.3 * U(rng);
        const double past = cone * Degree + SpotConeSlack + std::asin(small / D) + 0.01;
        if (past < 3.1)
        {
          ++outside;
          const glm::dvec3 far = ConePoint(apex, axis, D, past, 6.283185307179586 * U(rng));
          rejected += SpotConeMayReachBall(apex, axis, cosCone, far, small) ? 0 : 1;
        }
        // A ball holding the apex.
        EXPECT_TRUE(SpotConeMayReachBall(apex, axis, cosCone, apex - 0.5 * d * axis, d));
      }
    }
  }
  EXPECT_GT(outside, 10000);
  EXPECT_EQ(rejected, outside);
}

// The cosine form (SpotCone) answers as the angle form of the file description, phi -
// asin(rho / D) <= cone + slack evaluated with inverse trigonometry in long double,
// wherever the two angles differ by more than 1e-9 radians (5e-8 near the axis): balls within a few
// slacks of the widened cone's edge, near the axis (cones of 0 degrees, tiny balls), at the apex's
// side (cones near 90 degrees, large balls: a + asin(rho / D) >= pi) and at every scale;
// and the slacks the product uses (SpotConeSlack, the far field's 1e-6) and none.
TEST(SpotBounds, CosineFormAnswersAsTheAngleForm)
{
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  long long inside = 0, outside = 0;
  for (const double slack : { SpotConeSlack, 1e-6, 0.0 })
  {
    for (const double scale : { 1e-3, 1.0, 1e6 })
    {
      for (const double cone : Cones)
      {
        const glm::dvec3 apex = scale * glm::dvec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
        const glm::dvec3 axis = RandomUnit(rng);
        const double cosCone = std::cos(cone * Degree);
        const SpotCone widened(apex, axis, cosCone, slack);
        for (int k = 0; k < 3000; ++k)
        {
          const double D = scale * std::pow(10.0, -2.0 + 3.0 * U(rng));
          const double rho =
            D * (k % 5 == 0 ? 0.999 * U(rng) : std::pow(10.0, -8.0 + 8.0 * U(rng)));
          const double b = std::asin(rho / D);
          // Centres a tiny or a small angle either side of the edge, or anywhere.
          const double offset = k % 3 == 0 ? 1e-7 * (2.0 * U(rng) - 1.0)
            : k % 3 == 1                   ? 1e-3 * (2.0 * U(rng) - 1.0)
                                           : 3.14159 * U(rng) - (cone * Degree + slack + b);
          const double phi =
            std::min(std::max(cone * Degree + slack + b + offset, 0.0), 3.14159265358979);
          const glm::dvec3 centre = ConePoint(apex, axis, D, phi, 6.283185307179586 * U(rng));
          const glm::dvec3 v = centre - apex;
          const long double cosPhi =
            static_cast<long double>(glm::dot(v, axis)) / static_cast<long double>(glm::length(v));
          const long double margin = std::acos(std::min(std::max(cosPhi, -1.0L), 1.0L)) -
            std::asin(static_cast<long double>(rho) / static_cast<long double>(glm::length(v))) -
            (std::acos(static_cast<long double>(cosCone)) + static_cast<long double>(slack));
          // Near the axis a cosine resolves angles to about 2e-8 radians, not 1e-9.
          const long double tolerance = cone * Degree + slack + b < 1e-3 ? 5e-8L : 1e-9L;
          if (margin < -tolerance)
          {
            ++inside;
            ASSERT_TRUE(widened.MayReachBall(centre, rho))
              << "cone " << cone << " scale " << scale << " slack " << slack << " margin "
              << static_cast<double>(margin);
          }
          else if (margin > tolerance)
          {
            ++outside;
            ASSERT_FALSE(widened.MayReachBall(centre, rho))
              << "cone " << cone << " scale " << scale << " slack " << slack << " margin "
              << static_cast<double>(margin);
          }
        }
      }
    }
  }
  EXPECT_GT(inside, 100000);
  EXPECT_GT(outside, 100000);
  // A cone of 120 degrees and a ball seen within 60 degrees of the apex's far side: their
  // angles sum to pi and more, so the ball meets the cone whatever its direction.
  const SpotCone wide(glm::dvec3(0.0), glm::dvec3(0, 0, 1), std::cos(120.0 * Degree), 0.0);
  for (const double phi : { 170.0, 175.0, 180.0 })
  {
    const glm::dvec3 centre =
      ConePoint(glm::dvec3(0.0), glm::dvec3(0, 0, 1), 2.0, phi * Degree, 0.3);
    EXPECT_TRUE(wide.MayReachBall(centre, 2.0 * std::sin(61.0 * Degree))) << phi;
    EXPECT_FALSE(wide.MayReachBall(centre, 2.0 * std::sin(0.5 * (phi - 125.0) * Degree))) << phi;
  }
  // A cone widened past pi passes everywhere; a ball holding the apex passes.
  const SpotCone everything(glm::dvec3(0.0), glm::dvec3(0, 0, 1), -1.0, 1e-3);
  EXPECT_TRUE(everything.MayReachBall(glm::dvec3(0, 0, -10), 1e-3));
  const SpotCone narrow(glm::dvec3(0.0), glm::dvec3(0, 0, 1), 1.0, 0.0);
  EXPECT_TRUE(narrow.MayReachBall(glm::dvec3(0.5, 0, 0), 1.0));
  EXPECT_FALSE(narrow.MayReachBall(glm::dvec3(0, 0, -10), 1.0));
}

// The list shader's float test (mirrored above) passes wherever the double test does,
// balls near the cone's edge and near the apex included.
TEST(SpotBounds, ShaderFormulaPassesWhereverTheCoreTestDoes)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  long long checked = 0;
  for (const double scale : { 1e-3, 1.0, 1e3, 1e5 })
  {
    for (const double cone : Cones)
    {
      const glm::dvec3 apex = scale * glm::dvec3(U(rng) - 0.5, U(rng) - 0.5, -U(rng));
      const glm::dvec3 axis = RandomUnit(rng);
      const glm::vec3 axisF = glm::normalize(glm::vec3(axis));
      const double cosCone = std::cos(cone * Degree);
      for (int k = 0; k < 5000; ++k)
      {
        const double D = scale * std::pow(10.0, -3.0 + 3.5 * U(rng));
        const double rho = D * std::pow(10.0, -4.0 + 4.0 * U(rng));
        // Centres within a few slacks of where the test changes its answer.
        const double edge =
          cone * Degree + std::asin(std::min(rho / D, 1.0)) + SpotConeSlack * (2.0 * U(rng) - 1.0);
        const glm::dvec3 centre =
          ConePoint(apex, axis, D, std::max(edge, 0.0), 6.283185307179586 * U(rng));
        if (!SpotConeMayReachBall(apex, axis, cosCone, centre, rho))
        {
          continue;
        }
        ++checked;
        EXPECT_TRUE(ShaderConeTest(glm::vec3(apex), axisF, static_cast<float>(cosCone),
          glm::vec3(centre), static_cast<float>(rho)))
          << "cone " << cone << " scale " << scale << " D " << D << " rho " << rho;
      }
    }
  }
  EXPECT_GT(checked, 50000);
}

// The reference with cones keeps every cluster that a point of a spot light's sector
// falls in; the CPU's quads (ComputeViewData with SpotConeCulling) cover every pair the
// reference keeps and record the cone for the list pass; and the cones cut the pairs.
TEST(SpotBounds, ReferenceAndQuadsKeepEveryClusterASpotLightReaches)
{
  const double nearVC = 0.5, farVC = 40.0;
  const glm::dmat4 P = ClusteredLightingTest::Perspective(50.0, 4.0 / 3.0, nearVC, farVC);
  const ClusterGridParams g =
    ClusteredLightingTest::MakeGrid(16, 8, 24, 160, 120, nearVC, farVC, SlicingScheme::Exponential);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<PreparedLight> lights;
  for (int i = 0; i < 240; ++i)
  {
    PreparedLight l{};
    // Some behind the camera or straddling the near plane.
    l.PositionWC = glm::dvec3(-6.0 + 12.0 * U(rng), -4.0 + 8.0 * U(rng), 1.0 - 20.0 * U(rng));
    l.Radius = 0.3 + 6.0 * U(rng);
    l.Color = glm::dvec3(1.0);
    l.Exponent = 1.0;
    l.Attenuation = glm::dvec3(1.0, 0.0, 1.0);
    l.CosCone = std::cos(Cones[i % 12] * Degree);
    l.DirectionWC = i % 5 == 0 ? glm::dvec3(0, 0, 1) : RandomUnit(rng); // some face the camera
    l.ExplicitRadius = std::numeric_limits<double>::infinity();
    lights.push_back(l);
  }
  std::vector<ReferenceLight> cones, spheres;
  for (const PreparedLight& l : lights)
  {
    spheres.push_back({ l.PositionWC, l.Radius });
    ReferenceLight r{ l.PositionWC, l.Radius };
    r.AxisVC = l.DirectionWC;
    r.CosCone = l.CosCone;
    cones.push_back(r);
  }
  const ReferenceAssignment ref = ComputeReferenceAssignment(cones, g, P, nearVC, farVC);
  const ReferenceAssignment whole = ComputeReferenceAssignment(spheres, g, P, nearVC, farVC);

  // Truth: sampled points of each sector inside the frustum.
  int sampled = 0, missing = 0;
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    const PreparedLight& l = lights[i];
    const double theta = std::acos(l.CosCone);
    for (int k = 0; k < 3000; ++k)
    {
      const double d = l.Radius * std::cbrt(U(rng)) * (1.0 - 1e-9);
      const double phi = k % 2 ? theta : theta * std::sqrt(U(rng));
      const glm::dvec3 p =
        ConePoint(l.PositionWC, l.DirectionWC, d, phi, 6.283185307179586 * U(rng));
      const glm::dvec4 clip = P * glm::dvec4(p, 1.0);
      const double depth = -p.z;
      if (!(clip.w > 0.0) || depth < nearVC || depth > farVC)
      {
        continue;
      }
      const double x = clip.x / clip.w, y = clip.y / clip.w;
      if (std::abs(x) >= 1.0 || std::abs(y) >= 1.0)
      {
        continue;
      }
      const int tx = std::min(static_cast<int>(0.5 * (x + 1.0) * g.TilesX), g.TilesX - 1);
      const int ty = std::min(static_cast<int>(0.5 * (y + 1.0) * g.TilesY), g.TilesY - 1);
      const int s = ComputeSliceIndex(depth, g);
      ++sampled;
      if (!ref.Contains(ComputeClusterId(tx, ty, s, g), static_cast<int>(i)))
      {
        ++missing;
        ADD_FAILURE() << "light " << i << " (cone " << Cones[i % 12] << ") misses cluster (" << tx
                      << ", " << ty << ", " << s << ")";
        if (missing > 5)
        {
          return;
        }
      }
    }
  }
  EXPECT_GT(sampled, 100000);
  EXPECT_EQ(missing, 0);

  // The quads cover every pair the reference keeps, and carry the cone.
  ViewParameters v; // world = view
  v.VCDC = P;
  v.Grid = g;
  const ViewData data = ComputeViewData(lights, v);
  std::set<std::pair<int, int>> covered; // (cluster, light)
  for (int q = 0; q < data.NumberOfQuads; ++q)
  {
    const float* f = &data.Quads[static_cast<std::size_t>(q) * FloatsPerQuad];
    const int light = static_cast<int>(f[5]);
    EXPECT_EQ(f[6], static_cast<float>(lights[static_cast<std::size_t>(light)].CosCone));
    for (int ty = static_cast<int>(f[1]); ty <= static_cast<int>(f[3]); ++ty)
    {
      for (int tx = static_cast<int>(f[0]); tx <= static_cast<int>(f[2]); ++tx)
      {
        covered.insert({ ComputeClusterId(tx, ty, static_cast<int>(f[4]), g), light });
      }
    }
  }
  std::uint64_t pairs = 0, pairsWhole = 0, uncovered = 0;
  for (int id = 0; id < g.GetNumberOfClusters(); ++id)
  {
    for (int i = 0; i < static_cast<int>(lights.size()); ++i)
    {
      pairsWhole += whole.Contains(id, i) ? 1 : 0;
      if (ref.Contains(id, i))
      {
        ++pairs;
        uncovered += covered.count({ id, i }) ? 0 : 1;
        EXPECT_TRUE(whole.Contains(id, i));
      }
    }
  }
  EXPECT_EQ(uncovered, 0u);
  EXPECT_GT(pairs, 10000u);
  // The cones keep under two thirds of the spheres' pairs here.
  EXPECT_LT(static_cast<double>(pairs), 0.67 * static_cast<double>(pairsWhole));
  std::cout << "[ spot cones ] " << pairs << " of " << pairsWhole << " sphere pairs, "
            << data.NumberOfQuads << " quads\n";

  // Without SpotConeCulling: the spheres' rectangles and no cone for the list pass.
  v.SpotConeCulling = false;
  const ViewData off = ComputeViewData(lights, v);
  EXPECT_GT(off.ClusterCoverage, data.ClusterCoverage);
  for (int q = 0; q < off.NumberOfQuads; ++q)
  {
    EXPECT_EQ(off.Quads[static_cast<std::size_t>(q) * FloatsPerQuad + 6], -2.0f);
  }
}
