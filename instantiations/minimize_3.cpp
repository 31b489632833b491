// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Group 3 of the shared instantiations (extern_templates.h), of dimension 2.

#include "extern_templates.h"

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

DISTORTION_GROUP_3(2, )

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL
