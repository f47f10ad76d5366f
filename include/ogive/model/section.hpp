// The cross-section's law: how the axis' axial strain and curvature follow from the normal force and the
// bending moment, for the two sections ogive knows (model layer; scaled units of arch_model.hpp).
//
// elastic     the linear Timoshenko section: eps = N / (E A), kappa = M / (E I).
// no_tension  a rectangular section of depth t that carries no tension (Heyman's masonry, elastic in
//             compression). While the resultant stays in the kern (|M / N| <= t / 6, |e| <= 100 %) the
//             whole section is compressed and the law is the linear one. Beyond, only a depth
//                 c = 3 u,   u = t / 2 - |M / N|
//             works (the stress falls linearly from the compressed face to zero at depth c, its
//             resultant P = -N at c / 3 from that face, i.e. at |M / N| from the axis). With the plane
//             section's strain at the compressed face eps_f = 2 P / (E c):
//                 kappa = sign(M) eps_f / c = sign(M) 2 P / (9 E u^2)
//                 eps   = -eps_f (1 - t / (2 c)) = -(2 P / (3 E u)) (1 - t / (6 u))   (at the axis)
//             Both meet the linear law with a continuous first derivative at the kern's edge (u = t/3).
//             Defined for N < 0 and |M / N| < t / 2 only: there the resultant leaves the section
//             (a hinge has formed: kappa -> infinity). Shear stays the linear k G A law (the cracked
//             part still interlocks; the shear strain is small beside the curvature's effect).
// In the model's scaled units (arch_model.hpp: N~ = N / (w L), M~ = M / (w L^2), t~ = t / L) the
// elastic law reads eps~ = a_N N~ (a_N = t~^2 / 12), kappa~ = M~, and the cracked one, with P~ = -N~,
//     kappa~ = sign(M~) P~ t~^3 / (54 u~^2),   eps~ = -(P~ t~^3 / (18 u~)) (1 - t~ / (6 u~)).
#pragma once

namespace ogive {

enum class SectionKind { elastic, no_tension };

// The strains of one section and their derivatives with respect to N and M (scaled).
struct SectionStrain {
  double eps = 0, kappa = 0;                // axial strain term (Ux', Uy' use it) and curvature (psi')
  double eps_N = 0, eps_M = 0;              // d eps / dN, d eps / dM
  double kappa_N = 0, kappa_M = 0;          // d kappa / dN, d kappa / dM
  double compressed_depth = 1;              // c / t: 1 while the whole section is compressed
  bool cracked = false;                     // the resultant lies beyond the kern (|e| > 100 %)
  bool admissible = true;                   // N < 0 and |M / N| < t / 2 (no_tension); always for elastic
};

// The law at scaled N~, M~ for a section of scaled depth t~ (a_N = t~^2 / 12). For no_tension outside
// its domain, admissible is false and the other fields are meaningless.
SectionStrain section_strain(SectionKind kind, double N, double M, double t);

// The greatest compressive stress in a section of depth t and unit width, positive in compression, and
// its derivatives with respect to N and M. With P = -N > 0 and m = |M|: the elastic section's linear
// stress, sigma = P / t + 6 m / t^2 (either section while the resultant is in the kern, m <= P t / 6);
// the no-tension section beyond the kern, the triangular block over the compressed depth c = 3 u,
// u = t/2 - m / P: sigma = 2 P / (3 u). The two meet with a continuous first derivative at the kern's
// edge. sigma is NaN (and the derivatives 0) where N is not a compression, or where the no-tension
// section's resultant lies on or beyond a face (u <= 0: no finite stress carries it). Any consistent
// units (SI: N/m, N m/m and m give Pa; the model's scaled ones give scaled stresses).
struct CompressiveStress {
  double sigma = 0;
  double d_N = 0, d_M = 0;  // d sigma / dN, d sigma / dM
};
CompressiveStress compressive_stress(SectionKind kind, double N, double M, double t);

}  // namespace ogive
