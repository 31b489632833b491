// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Group 4 of the shared instantiations (extern_templates.h), of dimension 3.

#include "extern_templates.h"

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

DISTORTION_GROUP_1(3, )

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL
