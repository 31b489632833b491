// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Empty: the target of this file only holds the precompiled extern_templates.h
// (instantiations/CMakeLists.txt).
