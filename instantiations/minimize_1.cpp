// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Group 1 of the shared instantiations (extern_templates.h), of dimension 2.

#include "extern_templates.h"

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

DISTORTION_GROUP_1(2, )

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL
