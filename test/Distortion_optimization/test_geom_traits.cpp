// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The geometric traits decide the orientations (CGAL::parameters::geom_traits): a file of its own,
// since each kernel compiles the optimizer again (an exact-constructions kernel among them).

#include "test_meshes.h"

#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <gtest/gtest.h>

using namespace test_meshes;

namespace {

const Map affine = [](const Point_2& p) { return Point_2(2 * p.x() + 0.7 * p.y() + 1, -0.4 * p.x() + 0.8 * p.y()); };

// A kernel whose orientation predicate counts its calls: proves that geom_traits is the one used.
std::size_t orientation_calls = 0;
struct Counting_kernel : K
{
  struct Orientation_2
  {
    CGAL::Orientation operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
    {
      ++orientation_calls;
      return K().orientation_2_object()(p, q, r);
    }
  };
  Orientation_2 orientation_2_object() const { return {}; }
};

} // namespace

TEST(MinimizeDistortion, GeomTraitsDecideOrientations)
{
  Noisy_map a(affine, 0.02), b(affine, 0.02), c(affine, 0.02);
  const auto ra = CGAL::minimize_distortion(a.mesh, a.uv, DO::Conformal_dilatation());
  // The traits' predicates are asked, and they agree with the default's, so the run is the same
  // to the last bit, with an exact-constructions kernel too.
  orientation_calls = 0;
  const auto rb = CGAL::minimize_distortion(b.mesh, b.uv, DO::Conformal_dilatation(),
                                            CGAL::parameters::geom_traits(Counting_kernel()));
  EXPECT_GT(orientation_calls, b.mesh.number_of_faces());
  const auto rc = CGAL::minimize_distortion(c.mesh, c.uv, DO::Conformal_dilatation(),
                                            CGAL::parameters::geom_traits(CGAL::Exact_predicates_exact_constructions_kernel()));
  EXPECT_EQ(ra.final_energy, rb.final_energy);
  EXPECT_EQ(ra.final_energy, rc.final_energy);
  EXPECT_EQ(ra.iterations, rc.iterations);
  for(auto v : a.mesh.vertices()) {
    EXPECT_EQ(a.uv[v], b.uv[v]);
    EXPECT_EQ(a.uv[v], c.uv[v]);
  }
  orientation_calls = 0;
  EXPECT_EQ(CGAL::compute_distortion(b.mesh, b.uv, DO::ARAP(), CGAL::parameters::geom_traits(Counting_kernel())).inverted_cells, 0u);
  EXPECT_EQ(orientation_calls, 2 * b.mesh.number_of_faces());   // each source and each target face once
}

