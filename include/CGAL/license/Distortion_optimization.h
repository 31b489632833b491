// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The license check of the package, in the form of CGAL's own license headers: the package uses
// GPL packages of CGAL (Mesh_3, AABB_tree, Surface_mesh_parameterization, Polygon_mesh_processing),
// so it is GPL itself unless a commercial license covers it.

#ifndef CGAL_LICENSE_DISTORTION_OPTIMIZATION_H
#define CGAL_LICENSE_DISTORTION_OPTIMIZATION_H

#include <CGAL/config.h>
#include <CGAL/license.h>

#ifdef CGAL_DISTORTION_OPTIMIZATION_COMMERCIAL_LICENSE

#  if CGAL_DISTORTION_OPTIMIZATION_COMMERCIAL_LICENSE < CGAL_RELEASE_DATE
#    if defined(CGAL_LICENSE_WARNING)
       CGAL_pragma_warning("Your commercial license for CGAL does not cover "
                           "this release of the Distortion Optimization package.")
#    endif
#    ifdef CGAL_LICENSE_ERROR
#      error "Your commercial license for CGAL does not cover this release \
              of the Distortion Optimization package. \
              You get this error, as you defined CGAL_LICENSE_ERROR."
#    endif
#  endif

#else // no CGAL_DISTORTION_OPTIMIZATION_COMMERCIAL_LICENSE

#  if defined(CGAL_LICENSE_WARNING)
     CGAL_pragma_warning("\nThe macro CGAL_DISTORTION_OPTIMIZATION_COMMERCIAL_LICENSE is not defined."
                         "\nYou use the CGAL Distortion Optimization package under "
                         "the terms of the GPLv3+.")
#  endif
#  ifdef CGAL_LICENSE_ERROR
#    error "The macro CGAL_DISTORTION_OPTIMIZATION_COMMERCIAL_LICENSE is not defined.\
            You use the CGAL Distortion Optimization package under the terms of \
            the GPLv3+. You get this error, as you defined CGAL_LICENSE_ERROR."
#  endif

#endif // no CGAL_DISTORTION_OPTIMIZATION_COMMERCIAL_LICENSE

#endif // CGAL_LICENSE_DISTORTION_OPTIMIZATION_H
