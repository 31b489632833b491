// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Group 1 of the shared instantiations (extern_templates.h), of dimension 2.

#define DISTORTION_INSTANTIATE 1
#include "extern_templates.h"
