// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Any_measure on tetrahedral maps: the same runs, to the last bit, as with the measure's own type,
// with the schedules that each kind of measure takes (Newton steps, a smooth model's).

#include "test_mesh_3.h"

#include <CGAL/Distortion_optimization/Any_measure.h>
#include <CGAL/Distortion_optimization/measure_by_name.h>
#include <CGAL/Distortion_optimization/volume_maps.h>
#include <CGAL/minimize_distortion.h>

#include <boost/property_map/function_property_map.hpp>

#include <gtest/gtest.h>

#include <string>

namespace {

namespace DO = CGAL::Distortion_optimization;

TEST(AnyMeasure, TetrahedralMapsAreTheSameBitsAsWithTheMeasuresOwnType)
{
  const C3t3 c3t3 = mesh_sphere(0.25);
  Target_storage start;
  DO::map_vertices(c3t3, Target_map(start), radial);
  ASSERT_EQ(inverted(c3t3, start), 0u);
  // Fixed boundary (the Laplacian's or Newton's steps) and nothing fixed (a smooth model's steps
  // for the dilatations); the measures are among those whose optimizer the tests share
  // (instantiations/extern_templates.h).
  const auto compare = [&](const auto& measure) {
    const std::string name = measure.name();
    for(const bool fixed : {true, false}) {
      Target_storage a = start, b = start;
      const auto run = [&](auto& storage, const auto& m) {
        const auto np = CGAL::parameters::number_of_iterations(6);
        if(fixed) return CGAL::minimize_distortion(c3t3, Target_map(storage), m, np);
        return CGAL::minimize_distortion(c3t3, Target_map(storage), m,
                                         np.vertex_is_constrained_map(boost::make_function_property_map<Vertex_handle>(
                                           [](Vertex_handle) { return false; })));
      };
      const DO::Result own = run(a, measure);
      const DO::Result held = run(b, DO::measure_from_name(name));
      EXPECT_EQ(own.final_energy, held.final_energy) << name << (fixed ? "" : ", nothing fixed");
      EXPECT_EQ(own.iterations, held.iterations) << name;
      EXPECT_LT(held.final_energy, held.initial_energy) << name;
      for(const auto& [v, p] : a) EXPECT_EQ(p, b.at(v)) << name;
    }
  };
  compare(DO::Conformal_dilatation());   // a smooth model's Newton steps with nothing fixed
  compare(DO::Isometric_dilatation());
  compare(DO::Symmetric_dirichlet());    // its own Newton steps
  compare(DO::MIPS());
}

} // namespace
