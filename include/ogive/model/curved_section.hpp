// The compliance of a thick circular bar's rectangular section from plane elasticity (docs/model.md,
// "Beam models"): the curved bar's section law where the end loads of a circular bar are carried by the
// exact stresses of Golovin's pure bending and Michell's end force (Timoshenko and Goodier, sections 29
// and 31), radial stress and Poisson's ratio included, not by Winkler-Bach's hyperbolic hoop stress alone.
//
// A section of the bar (centroid radius R, depth t, rho = t / (2 R) in [0, 1)) carries the normal force
// N, the moment M about its centroid and the shear force V. Away from its ends, the bar's stresses are
// Golovin's and Michell's fields, which depend on the section's (N, M, V) alone; their complementary
// energy per length of the centroid's axis is
//   U = N^2 axial / (2 E A) + N M coupling / (E A R) + M^2 bending / (2 E I) + V^2 shear / (2 k0 G A)
// (plane stress, E and nu; plane strain: E / (1 - nu^2) and nu / (1 - nu) in their place; k0 = 5/6,
// the straight rectangle's shear coefficient of the same energy), and by Castigliano it is the beam whose
// end displacements are the bar's. As rho -> 0, axial, bending and shear tend to 1 (the straight beam)
// and coupling to 1 + 6 nu / 5 (Winkler-Bach's 1, plus the radial stress' Poisson strain along the axis).
// Winkler-Bach's law is this without the radial stress: axial 1, coupling 1, bending I / (A R e).
#pragma once

namespace ogive {

//
// A body force across the section (the self-weight), whose part normal to the axis is q per length of
// the axis (outward from the centre of curvature), is not carried by these stresses alone: the annulus
// under a uniform radial body force, less the modes of its own (N, M), is the load's own stress across
// the depth (its radial stress, and the hoop stress that balances it), zero on both faces and without
// resultants. Its complementary energy against the modes of (N, M) adds the load terms
//   N eps0 + M kappa0,  eps0 = load_extension q t / (E A),  kappa0 = load_curvature q / (E A)
// to U: the section strains by eps0 and curves by kappa0 (M tension on the outer face positive) under
// the load alone. As rho -> 0, load_curvature tends to -nu / 5 (the straight beam's transverse stress
// through Poisson's ratio) and load_extension to 0 (odd in rho). The part of the body force along the
// axis brings a shear strain of order rho^2 of the shear's (4e-4 at rho 0.2), which is not kept.
struct CurvedSection {
  double axial = 1, coupling = 1, bending = 1, shear = 1;
  double load_extension = 0, load_curvature = 0;
};

// rho = t / (2 R) in [0, 1), nu in (-1, 0.5]: the four factors above. Below rho = 1e-3 each is its
// limit plus its rho^2 term (the stress modes' constants cancel there beyond round-off).
CurvedSection curved_section(double rho, double nu);

// A face held whole (a clamped springing) is stiffer than the beam's clamped end within about a depth of
// it: the held face stops the section's warping under shear and its lateral (Poisson) strain. Beyond
// Timoshenko's clamped beam (k0 = 5/6) the bar's displacements and rotation a few depths from such a face
// are those of an end that moves, per unit width, by
//   NN N / E along the axis, VV V / E + VM M / (E t) across it, and turns by VM V / (E t) + MM M / (E t^2)
// (the compliance is symmetric: Maxwell), N, V and M the forces of the bar on the face, in the frame of
// the axis leaving the face (V a quarter turn anticlockwise from N, M anticlockwise); E and nu plane
// stress', in plane strain E / (1 - nu^2) and nu / (1 - nu). These are plane elasticity's: a straight
// strip held whole at one end and loaded by Saint-Venant's stresses at the other (CalculiX, 32 quadratic
// elements through the depth, benchmarks/continuum strip: held.csv), tabulated over nu from -0.9 to 0.97
// and interpolated by quadratics (beyond, the end ones); at nu = 0 only VV (-0.035, the warping) is left; at nu = 0.2 VV -0.043, VM -0.017,
// MM -0.031, NN -0.006: all negative, a stiffer end. nu in (-1, 1).
// A curved bar's face (t_kappa = t / R there, positive where the centre of curvature lies opposite the
// face's V: an arch's springing, its V towards the extrados) adds a coupling of N and the turn, by Maxwell of M and the
// stretch: NM N / (E t) to the turn and NM M / (E t) to the stretch, and moves the other four. Plane
// elasticity's: the semicircle's half (R = L / 2, no weight) held whole at its springing face and loaded
// at its crown face by the thick circular bar's own section stresses of N, V and M (Golovin's), less the
// bar's compliance (CalculiX, 32 quadratic elements through the depth, benchmarks/continuum ring:
// ring.csv) at t_kappa 0.2 to 0.6, with the straight strip's at 0, interpolated by quadratics over nu and
// then over t_kappa (beyond 0.6, the end ones: not measured, the quarter ring there is shorter than the
// face's zone). At nu = 0.2 and t_kappa 0.4: NM +0.017 and MM -0.063
// (the strip's -0.031). NM is odd in t_kappa (the face mirrored), the others even.
struct HeldFace {
  double NN = 0, VV = 0, VM = 0, MM = 0, NM = 0;
};
HeldFace held_face(double nu, double t_kappa = 0);

// A pointed crown's wedge: where the two legs meet at a point, the body between the beam's radial crown
// section (through the axis' crown point) and the crown's vertical line is not a bar's section; within
// about a depth of the crown it makes the crown a joint between the legs: each leg's crown section turns
// against the crown's symmetry line, per unit width, by
//   crown_wedge(theta_c) M / (E t^2)
// (M the crown's moment, t the depth there; the two legs against each other by twice that) beyond the
// bar's own turn and its kink's coupling. Negative (the wedge stiffens the crown), zero as theta_c -> 0 (a
// smooth crown), of order t / L against the legs' bending, as a held face's end zone. Plane elasticity's:
// the crown's last 4 t of pointed arches at t/L 0.02 with their pointed crown less the beam's radial one
// (CalculiX, 4 to 16 quadratic elements through the depth, extrapolated; benchmarks/continuum wedge:
// wedge.csv), at nu = 0: with nu the wedge's own turn does not change (within 0.2 % at nu 0.2), while the
// radial crown of that measurement, a rigid line, stops the section's Poisson strain as the beam's crown
// does not. Tabulated over theta_c (radians, the crown tangent's angle to the horizontal) from 0 to 75
// degrees (-0.418 at 30, the equilateral arch; -15.5 at 75), interpolated by quadratics; theta_c in
// [0, pi / 2). Beyond 75 degrees the last three nodes' quadratic, an extrapolation: the wedge is longer
// than the depth there and the measurement's 4 t no longer holds its zone.
double crown_wedge(double theta_c);

}  // namespace ogive
