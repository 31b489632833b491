// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Group 6 of the shared instantiations (extern_templates.h), of dimension 3.

#define DISTORTION_INSTANTIATE 6
#include "extern_templates.h"
