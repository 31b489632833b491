// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tests' shared instantiations in 3D (extern_templates.h).

#define DISTORTION_TEST_INSTANTIATE 3
#include "extern_templates.h"

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

DISTORTION_TEST_INSTANTIATIONS(3, )

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL
