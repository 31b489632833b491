// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The shared instantiation of mesh_interior()'s Mesh_3 front end (extern_mesh_interior.h).

#define DISTORTION_INSTANTIATE_MESH_INTERIOR
#include "extern_mesh_interior.h"
