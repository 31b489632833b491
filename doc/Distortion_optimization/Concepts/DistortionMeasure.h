/*!
\ingroup PkgDistortionOptimizationMeasures
\cgalConcept

\anchor MeasureConcept

The concept `DistortionMeasure` describes a distortion measure of a simplicial map in the sense of
section 2.1 of Naitsat, Saucan and Zeevi, "Geometry-based distortion measures for space
deformation": a function D(sigma_1, ..., sigma_n) of the signed singular values
sigma_1 >= ... >= sigma_{n-1} >= |sigma_n| of the Jacobian J of the map on one cell, together with
its exact derivative. The last singular value carries the sign of det J, so that sigma_n <= 0
means a degenerate or inverted cell (`CGAL::Distortion_optimization::Singular_values`).

`CGAL::compute_distortion()`, `CGAL::minimize_distortion()`,
`CGAL::Distortion_optimization::improve_mesh_quality()` and the combinators
`CGAL::Distortion_optimization::Product` and `CGAL::Distortion_optimization::Weighted_sum` accept
any model. The members are templates in the dimension `n`, 2 for triangle meshes and 3 for
tetrahedral meshes: they are instantiated only for the dimension of the meshes a model is used on.

All members are `const`. With more than one thread (named parameter `number_of_threads`) the
package calls them concurrently on the same object: they must not modify shared state. The
combinators store copies of their operands, which must then be `CopyConstructible`.

A measure is <em>normalized</em> when D >= D(1, ..., 1) and D tends to +infinity as sigma_n tends
to 0 (Appendix C.1 of the paper), <em>symmetric</em> when D(sigma_1, ..., sigma_n) =
D(1 / sigma_n, ..., 1 / sigma_1) (C.6), and <em>regular</em> (RDM) when it is normalized and
symmetric (`CGAL::Distortion_optimization::is_regular()`).

Besides the required members, a model may provide the optional members described below; the
package detects them at compile time and uses them when they are there.

\cgalHasModel `CGAL::Distortion_optimization::Conformal_dilatation`
\cgalHasModel `CGAL::Distortion_optimization::Condition_number`
\cgalHasModel `CGAL::Distortion_optimization::MIPS`
\cgalHasModel `CGAL::Distortion_optimization::Isometric_dilatation`
\cgalHasModel `CGAL::Distortion_optimization::ARAP`
\cgalHasModel `CGAL::Distortion_optimization::Symmetric_dirichlet`
\cgalHasModel `CGAL::Distortion_optimization::Volume_distortion`
\cgalHasModel `CGAL::Distortion_optimization::Dirichlet`
\cgalHasModel `CGAL::Distortion_optimization::Untangling_barrier`
\cgalHasModel `CGAL::Distortion_optimization::Product<A, B>`, for models `A` and `B`
\cgalHasModel `CGAL::Distortion_optimization::Weighted_sum<A, B>`, for models `A` and `B`
\cgalHasModel `CGAL::Distortion_optimization::Custom_measure<ValueFunction, GradientFunction>`, the result of
              `CGAL::Distortion_optimization::make_measure()`
\cgalHasModel `CGAL::Distortion_optimization::Product_of_measures`
\cgalHasModel `CGAL::Distortion_optimization::Sum_of_measures`

\sa `CGAL::Distortion_optimization::value_on_rigid_maps()`
\sa `CGAL::Distortion_optimization::is_regular()`
\sa `CGAL::Distortion_optimization::with_measure()`
*/
class DistortionMeasure
{
public:

/// \name Required Members
/// @{

/*!
returns D(`s`), for the signed singular values `s` of a cell's Jacobian.

A normalized measure returns `+infinity` (`CGAL::Distortion_optimization::infinity`) where
`s[n-1] <= 0` (a degenerate or inverted cell). A value that is not a number makes
`CGAL::compute_distortion()` and `CGAL::minimize_distortion()` throw
`CGAL::Distortion_optimization::Invalid_input`.

It is also called at `s = (1, ..., 1)` by `CGAL::Distortion_optimization::value_on_rigid_maps()`,
which the stopping rule of `CGAL::minimize_distortion()` uses for a normalized measure, even when
the measure provides `value_of_invariants()`.
*/
template <int n>
double value(const CGAL::Distortion_optimization::Singular_values<n>& s) const;

/*!
returns the exact derivative of D at `s`: its entry `i` is dD/dsigma_i.

The package calls it only where `value(s)` is finite (the models of the package return NaN,
`CGAL::Distortion_optimization::not_a_number`, where the value is infinite), and does not call it
on cells when the measure provides `value_of_invariants()`; the combinators call it on their
operands.
*/
template <int n>
CGAL::Distortion_optimization::Singular_values<n> gradient(const CGAL::Distortion_optimization::Singular_values<n>& s) const;

/*!
returns whether the measure is normalized: D >= D(1, ..., 1) and D tends to +infinity as sigma_n
tends to 0.

For a normalized measure, the cells where `value()` is infinite (inverted or flat) make a start
map of `CGAL::minimize_distortion()` an error unless it is untangled first (named parameter
`untangle_first`); the package itself returns `+infinity` where det J <= 0 when the value comes
from `value_of_invariants()`; and the stopping rule measures the decrease of the energy against
the part of it above `CGAL::Distortion_optimization::value_on_rigid_maps()`.
*/
bool is_normalized() const;

/*!
returns whether the measure is symmetric in dimension `n`: D(sigma_1, ..., sigma_n) =
D(1 / sigma_n, ..., 1 / sigma_1).

Informative: read by `CGAL::Distortion_optimization::is_regular()` and by the combinators, not
by the evaluation or the minimization.
*/
template <int n>
bool is_symmetric() const;

/*!
returns the name of the measure, used in the messages of the exceptions (e.g. the measure that is
infinite on a cell of a start map) and in the names of the combinations. The built-in measures
return the names that `CGAL::Distortion_optimization::measure_names()` lists.
*/
std::string name() const;

/// @}

/// \name Optional Members
/// The package detects each of these members with SFINAE, for the dimension `n` of the mesh.
/// @{

/*!
returns D as a function of the invariants `I` of the Jacobian J (`I.norm2` = |J|_F^2,
`I.cofactor_norm2` = |cof J|_F^2, `I.det` = det J) and, if `dI` is not null, sets `*dI` to its
partial derivatives dD/d`norm2`, dD/d`cofactor_norm2` and dD/d`det`.

Detected when `m.template value_of_invariants<n, double>(I, dI)` is well-formed for a
`CGAL::Distortion_optimization::Jacobian_invariants<double>`. The package then evaluates every
cell through it instead of a singular value decomposition (`value()` and `gradient()` are not
called on cells), for one cell (`T` = `double`) or for several at once (`T` =
`CGAL::Distortion_optimization::lanes::Cell_lanes`, on which arithmetic, comparisons and `?:`
act lane by lane; `CGAL::Distortion_optimization::lanes` offers `broadcast()`, `sqrt()` and
`cbrt()`): it must compile for both. For a normalized measure its result is ignored where
det J <= 0 (the package returns `+infinity` there), and it is NaN where J has a non-finite entry.
It must agree with `value()`.
*/
template <int n, class T>
T value_of_invariants(const CGAL::Distortion_optimization::Jacobian_invariants<T>& I,
                      CGAL::Distortion_optimization::Jacobian_invariants<T>* dI) const;

/*!
returns the factor by which the global step of `CGAL::minimize_distortion()` (schedules `GLOBAL`
and `ALTERNATING`) weighs a cell in its reweighted Laplacian, for the cell's signed singular
values `s` in the current map.

Detected when `m.template laplacian_weight<n>(s)` is well-formed. A result that is not finite and
positive counts as 1; without this member every cell counts as 1. The combinators `Product` and
`Weighted_sum` return the larger weight of their operands, `Product_of_measures` the largest
weight of its factors.
*/
template <int n>
double laplacian_weight(const CGAL::Distortion_optimization::Singular_values<n>& s) const;

/*!
returns the matrix of second derivatives of D in the singular values `s` (ordered as
`gradient()`'s), where D is smooth and the cell is positively oriented.

Detected when `m.template hessian<n>(s)` is well-formed. With it, the global steps of
`CGAL::minimize_distortion()` may be projected Newton steps (`Distortion_optimization::Global_solver`):
the package builds each cell's Hessian in its vertices from `gradient()` and `hessian()` and
makes it positive semi-definite. For a pair of nearly equal singular values it uses the larger of
`h(i,i) - h(i,j)` (the limit where D is smooth and symmetric in them) and the gradient's difference
over the smallest gap resolved (a kink, as in a maximum of two terms). A result that is not finite on some cell makes that step use
the Laplacian instead. `Product` and `Weighted_sum` have it when both operands do.
*/
template <int n>
CGAL::Distortion_optimization::Singular_values_hessian<n>
hessian(const CGAL::Distortion_optimization::Singular_values<n>& s) const;

/// @}
};
