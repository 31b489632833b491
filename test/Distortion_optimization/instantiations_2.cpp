// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tests' shared instantiations in 2D (extern_templates.h).

#define DISTORTION_TEST_INSTANTIATE 2
#include "extern_templates.h"

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

DISTORTION_TEST_INSTANTIATIONS(2, )

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL
