/*!
\ingroup PkgHyperbolicOrbifoldTutteConcepts
\cgalConcept
\headerfile HyperbolicOrbifoldTraits_2.h <CGAL/hyperbolic_orbifold_Tutte.h>

The concept `HyperbolicOrbifoldTraits_2` describes the types, predicates and
constructions in the Poincar&eacute; disk that the package uses through its `Traits`
template parameter: `CGAL::Hyperbolic_orbifold_Tutte::Orbifold_tile`,
`CGAL::Hyperbolic_orbifold_Tutte::make_orbifold_tile()`,
`CGAL::Hyperbolic_orbifold_Tutte::Hyperbolic_orbifold_Tutte_parameterizer_3` and the
bijectivity certificate (`CGAL::Hyperbolic_orbifold_Tutte::Embedding_certificate`).
This list is exactly what that code calls, no more.

Points are Poincar&eacute;-disk coordinates: a `Point_2` \f$(x,y)\f$ stands for the
complex number \f$z = x + iy\f$ with \f$|z| < 1\f$. The Klein point of \f$z\f$ is
\f$2z/(1+|z|^2)\f$; geodesics are straight segments in the Klein model, so the
orientation of a geodesic triangle is the Euclidean orientation of its Klein image.

The orientation predicate must be exact on its input coordinates: the certificate's
verdict on triangle orientations (flipped and degenerate faces) is only as good as this
predicate. The constructions and the measures may be rounded; the certificate compares
their results with a tolerance.

The solver itself (Euclidean Tutte initialisation in the Klein model, Newton's method,
line search) works on `double` coordinates and does not call the traits.

\cgalHasModelsBegin
\cgalHasModels{CGAL::Hyperbolic_orbifold_Tutte::Poincare_disk_traits_2}
\cgalHasModelsEnd

\sa `CGAL::Hyperbolic_orbifold_Tutte::Hyperbolic_isometry_2`
*/
class HyperbolicOrbifoldTraits_2
{
public:
  /// \name Types
  /// @{

  /*!
  a field number type, constructible from `double` and convertible to `double`
  (implicitly and by `CGAL::to_double()`).
  */
  typedef unspecified_type FT;

  /*!
  a point of the open unit disk, in Poincar&eacute; coordinates; constructible from two
  `FT` (or two `double`), with accessors `x()` and `y()` returning `FT`. It is
  default constructible, copyable and assignable.
  */
  typedef unspecified_type Point_2;

  /*!
  the disk automorphisms used as side pairings of the orbifold tiles: must be
  `CGAL::Hyperbolic_orbifold_Tutte::Hyperbolic_isometry_2<double>` (the tile converts it
  to and from `Hyperbolic_isometry_2<long double>` to map points into the tile).
  */
  typedef unspecified_type Isometry;

  /// @}

  /// \name Predicate Types
  /// @{

  /*!
  a function object providing
  `CGAL::Orientation operator()(const Point_2& p, const Point_2& q, const Point_2& r)`,
  which returns the orientation of the geodesic triangle `pqr` (`CGAL::LEFT_TURN` when
  `r` is on the left of the geodesic from `p` to `q`, `CGAL::COLLINEAR` when the three
  points lie on one geodesic), decided exactly on the given coordinates.
  */
  typedef unspecified_type Hyperbolic_orientation_2;

  /// @}

  /// \name Construction Types
  /// @{

  /*!
  a function object providing `FT operator()(const Point_2& p, const Point_2& q)`,
  which returns the hyperbolic distance of `p` and `q`.
  */
  typedef unspecified_type Compute_hyperbolic_distance_2;

  /*!
  a function object providing
  `FT operator()(const Point_2& p, const Point_2& q, const Point_2& r)`, which returns
  the angle at `p`, in \f$[0,\pi]\f$, between the geodesics from `p` to `q` and from `p`
  to `r` (the model is conformal: it is the Euclidean angle between their tangents).
  */
  typedef unspecified_type Compute_hyperbolic_angle_2;

  /*!
  a function object providing `Point_2 operator()(const Point_2& p)`, which returns the
  Klein point \f$2p/(1+|p|^2)\f$ of the Poincar&eacute; point `p`.
  */
  typedef unspecified_type Construct_Klein_point_2;

  /*!
  a function object providing `Point_2 operator()(const Point_2& p, const Point_2& q)`,
  which returns the geodesic midpoint of `p` and `q`.
  */
  typedef unspecified_type Construct_hyperbolic_midpoint_2;

  /// @}

  /// \name Creation
  /// @{

  /// default constructor (used for the default arguments `Traits()`).
  HyperbolicOrbifoldTraits_2();

  /// copy constructor (the tile stores a copy of its traits).
  HyperbolicOrbifoldTraits_2(const HyperbolicOrbifoldTraits_2& other);

  /// @}

  /// \name Operations
  /// The functors are obtained from these member functions.
  /// @{

  /// returns a `Hyperbolic_orientation_2` object.
  Hyperbolic_orientation_2 hyperbolic_orientation_2_object() const;

  /// returns a `Compute_hyperbolic_distance_2` object.
  Compute_hyperbolic_distance_2 compute_hyperbolic_distance_2_object() const;

  /// returns a `Compute_hyperbolic_angle_2` object.
  Compute_hyperbolic_angle_2 compute_hyperbolic_angle_2_object() const;

  /// returns a `Construct_Klein_point_2` object.
  Construct_Klein_point_2 construct_Klein_point_2_object() const;

  /// returns a `Construct_hyperbolic_midpoint_2` object.
  Construct_hyperbolic_midpoint_2 construct_hyperbolic_midpoint_2_object() const;

  /// @}
};
