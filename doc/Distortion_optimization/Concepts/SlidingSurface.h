/*!
\ingroup PkgDistortionOptimizationConcepts
\cgalConcept

\anchor SlidingSurfaceConcept

The concept `SlidingSurface` describes a curve in the plane or a surface in space on which the
free boundary vertices of a map slide (named parameter
`CGAL::Distortion_optimization::parameters::sliding_boundary()`, Section
\ref ssecDistortionSliding of the user manual). A model answers one question: the point of the
surface closest to a position, and the unit normal there.

`CGAL::minimize_distortion()`, `CGAL::Distortion_optimization::untangle()` (also when
`CGAL::minimize_distortion()` untangles first) and
`CGAL::Distortion_optimization::improve_mesh_quality()` accept any model. They move a sliding
vertex in the tangent plane of the surface at its current position (the plane orthogonal to the
normal) and project each trial position back onto the surface with `project()`; the move is kept
only if the energy decreases and no valid cell inverts, whatever the surface returned. The
dimension `d` is that of the targets: 2 for triangle meshes (planar maps), 3 for
`Mesh_complex_3_in_triangulation_3`. A model needs `project()` only for the dimensions of the
meshes it is used on.

The positions are those of the map being optimized (the target map; the positions of
`CGAL::Distortion_optimization::improve_mesh_quality()`), in the user's coordinates converted to
`double` (the package undoes its internal scaling around each call).

The named parameter stores a copy of the model and the package copies it again: a model must be
`CopyConstructible`, and its copies must answer alike (they may share data, as the copies of a
`CGAL::Distortion_optimization::Triangle_surface` share its AABB tree).

`project()` is `const`. With more than one thread (named parameter `number_of_threads`) the
package calls it concurrently on the same object, for different vertices: it must not modify
shared state. For the output to be deterministic for a given number of threads, as the package
promises, its result must depend only on its arguments.

\cgalHasModel `CGAL::Distortion_optimization::Sphere_surface` (d = 2 and 3)
\cgalHasModel `CGAL::Distortion_optimization::Triangle_surface` (d = 3; it takes hints)

\sa `CGAL::Distortion_optimization::parameters::sliding_boundary()`
*/
class SlidingSurface
{
public:

/// \name Required Members
/// @{

/*!
returns the point of the surface closest to `x` and sets `normal` to a unit normal of the
surface at that point.

The package uses the normal only through the tangent plane (it removes from a gradient or a step
its part along the normal), so its orientation does not matter, but its length must be 1. Where
several points are equally close (the centre of a sphere), any one of them will do. The returned
point should be finite; a point off the surface, or one that is not the closest, is not an error
but defeats the descent. A start map's boundary vertex that is not on the surface moves onto it
with its first accepted move.

Shown as a template in `d`; a model may as well overload it for the dimensions it supports.
*/
template <std::size_t d>
std::array<double, d> project(const std::array<double, d>& x, std::array<double, d>& normal) const;

/// @}

/// \name Optional Member
/// The package detects this member at compile time, for the dimension `d` of the mesh, and then
/// calls it instead of the two-argument `project()`.
/// @{

/*!
the same as `project(x, normal)`, where `hint` speeds the query up: on entry it is -1 or the value
that the last call for the same vertex left in it, and the model may set it to any value that
helps the next query near the returned point (`Triangle_surface` stores the index of the
triangle of the closest point). The result must be a closest point whatever the hint.

Detected when `s.project(x, normal, hint)` is well-formed for a `const` model `s`,
`std::array<double, d>` arguments `x` and `normal`, and a `std::ptrdiff_t` lvalue `hint`. The
package keeps one hint per sliding vertex, starting at -1 for each run; no two threads use the
same vertex's hint at once, but queries for different vertices may run concurrently.
*/
template <std::size_t d>
std::array<double, d> project(const std::array<double, d>& x, std::array<double, d>& normal,
                              std::ptrdiff_t& hint) const;

/// @}
};
