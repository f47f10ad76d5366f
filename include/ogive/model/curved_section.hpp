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

struct CurvedSection {
  double axial = 1, coupling = 1, bending = 1, shear = 1;
};

// rho = t / (2 R) in [0, 1), nu in (-1, 0.5]: the four factors above. Below rho = 1e-3 each is its
// limit plus its rho^2 term (the stress modes' constants cancel there beyond round-off).
CurvedSection curved_section(double rho, double nu);

}  // namespace ogive
