// One entry point: Solution solve(const Scene&, const Options&): the dispatcher above the methods.
//
// Two error channels. Misuse (an invalid Scene or Options) throws std::invalid_argument naming the
// field and the rule it breaks. Numerical outcomes are a Status in the Solution (solution.hpp); the
// library never prints. It builds the model (the half arch for a symmetric scene unless
// Options::whole_arch, else the whole), runs the method asked for or, for Method::automatic, the
// smallest that meets rtol (the closed form where it applies, the quadrature method, then verified
// shooting with 1, 2, 4 ... 64 segments and tighter CVODE tolerances), verifies CVODE solves by two 16
// and 256 times tighter (the estimate: the larger of the difference from the looser and twice that
// from the tighter), and judges every solution against rtol (within_tolerance). A no-tension scene is
// solved by Newton (no_tension.hpp): for auto its quadrature form first (explicit forces, adaptive
// Gauss-Kronrod: milliseconds), then single shooting, then multiple shooting with 8 segments (and CVODE
// 10 times tighter) if that is not verified, each verified by a second solve at rtol / 16; --method
// quadrature, shooting and multiple-shooting run one of them; the closed form does not apply. Auto
// always verifies (Options::verify off applies to the methods named). The work of one no-tension scene is
// bounded by counts, so that it ends the same way on any machine: Newton's 30 iterations of at most 40
// halvings each, 40 solves a continuation path, a Newton shooting trial given up beyond 4 times the
// costliest successful evaluation's right-hand sides (at least 5 000), and over all the scene's solves at
// most 10 000 000 quadrature integrand evaluations and 2 000 000 CVODE right-hand sides; a scene that
// runs out is not_converged, the message naming the budget.
#pragma once

#include "ogive/model/arch_model.hpp"
#include "ogive/model/scene.hpp"
#include "ogive/core/solution.hpp"

namespace ogive {

// `previous`: a solved neighbouring scene, for the no-tension section (Scene::section): its springing state
// is Newton's first guess, and when Newton fails from it the support movements are traced from the
// previous scene's to this one's in steps that halve until each converges (continuation; the other
// fields of the two scenes must be equal for the tracing, else it starts from no movement). Ignored for
// the elastic section, whose solution is unique and direct.
Solution solve(const Scene& scene, const Options& options = {}, const Solution* previous = nullptr);

}  // namespace ogive
