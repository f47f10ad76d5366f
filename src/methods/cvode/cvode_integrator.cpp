#include "methods/cvode/cvode_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <numeric>
#include <stdexcept>

#include <Eigen/LU>

#include <cvode/cvode.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>

namespace ogive {
namespace {

// RAII handles for the SUNDIALS objects.
struct ContextDeleter { void operator()(SUNContext c) const { SUNContext_Free(&c); } };
struct VectorDeleter { void operator()(_generic_N_Vector* v) const { N_VDestroy(v); } };
struct MatrixDeleter { void operator()(_generic_SUNMatrix* m) const { SUNMatDestroy(m); } };
struct LinearSolverDeleter { void operator()(_generic_SUNLinearSolver* s) const { SUNLinSolFree(s); } };
struct NonlinearSolverDeleter { void operator()(_generic_SUNNonlinearSolver* s) const { SUNNonlinSolFree(s); } };
struct CvodeDeleter { void operator()(void* mem) const { CVodeFree(&mem); } };

using ContextHandle = std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter>;
using VectorHandle = std::unique_ptr<_generic_N_Vector, VectorDeleter>;
using MatrixHandle = std::unique_ptr<_generic_SUNMatrix, MatrixDeleter>;
using LinearSolverHandle = std::unique_ptr<_generic_SUNLinearSolver, LinearSolverDeleter>;
using NonlinearSolverHandle = std::unique_ptr<_generic_SUNNonlinearSolver, NonlinearSolverDeleter>;
using CvodeHandle = std::unique_ptr<void, CvodeDeleter>;

std::string flag_name(int flag) {
  char* name = CVodeGetReturnFlagName(flag);  // malloc'd by SUNDIALS
  std::string out = name ? name : "CV_UNKNOWN";
  std::free(name);
  return out;
}

// Setup calls cannot fail for valid arguments; if one does, it is a programming error.
void check(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(std::string(call) + " failed: " + flag_name(flag));
}


// ---------------------------------------------------------------------------------------------------
// ogive's own N_Vector (N_VNewEmpty and its operation table). Debian's libsundials (6.4.1+dfsg1-3) is
// compiled without optimisation, and for the short vectors here (42 entries) CVODE's time went mostly
// into its serial vector loops (callgrind: over half of all instructions). These are the same loops,
// compiled with the project's flags; CVODE clones every work vector from the one given to CVodeInit, and a
// clone copies the table, so every vector CVODE uses is one of these.
namespace vector {

struct Content {
  sunindextype length = 0;
  sunrealtype* data = nullptr;
  bool owns_data = false;
  // The ends of the independent problems the state holds, ascending, the last = length (one block: the
  // whole state). The weighted RMS norm is the largest of the blocks' own norms.
  std::shared_ptr<const std::vector<sunindextype>> block_ends;
};

Content& content(N_Vector v) { return *static_cast<Content*>(v->content); }
sunrealtype* data(N_Vector v) { return content(v).data; }
sunindextype size(N_Vector v) { return content(v).length; }

N_Vector_ID get_id(N_Vector) { return SUNDIALS_NVEC_CUSTOM; }
void destroy(N_Vector v) {
  if (!v) return;
  if (v->content) {
    if (content(v).owns_data) delete[] content(v).data;
    delete static_cast<Content*>(v->content);
    v->content = nullptr;
  }
  N_VFreeEmpty(v);
}
N_Vector clone_empty(N_Vector w) {
  N_Vector v = N_VNewEmpty(w->sunctx);
  if (!v) return nullptr;
  if (N_VCopyOps(w, v) != 0) {
    N_VFreeEmpty(v);
    return nullptr;
  }
  v->content = new Content{size(w), nullptr, false, content(w).block_ends};
  return v;
}
N_Vector clone(N_Vector w) {
  N_Vector v = clone_empty(w);
  if (!v) return nullptr;
  content(v).data = new sunrealtype[static_cast<std::size_t>(size(w))]();
  content(v).owns_data = true;
  return v;
}
void space(N_Vector v, sunindextype* real_words, sunindextype* integer_words) {
  *real_words = size(v);
  *integer_words = 1;
}
sunrealtype* array_pointer(N_Vector v) { return data(v); }
void set_array_pointer(sunrealtype* d, N_Vector v) { content(v).data = d; }
sunindextype length(N_Vector v) { return size(v); }

// The loops that CVODE runs most, compiled twice where the compiler can: for AVX2 (4 doubles per
// instruction) and for the baseline, chosen once at load time by the CPU. FMA is not enabled, so both
// clones round alike and results do not depend on the machine.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define OGIVE_VECTOR_LOOP __attribute__((target_clones("avx2", "default")))
#else
#define OGIVE_VECTOR_LOOP
#endif
// CVODE's vectors in one operation are separate arrays or the same one, never partly overlapping, so no
// iteration of an elementwise loop reads what another writes: the compiler is told so (GCC's ivdep), and
// emits no overlap checks (they were a quarter of the instructions of a 24-number sum).
#if defined(__GNUC__) && !defined(__clang__)
#define OGIVE_INDEPENDENT _Pragma("GCC ivdep")
#else
#define OGIVE_INDEPENDENT
#endif

// Every loop below is a template on the vector's length N, fixed at compile time for the lengths that
// shooting uses (1 to 5 columns of 6) and 0 for any other (then read from the vector): a fixed length
// turns a loop of 24 numbers into six AVX2 instructions with no trip-count logic. For vectors this short
// the logic was most of a kernel's cost (callgrind: 85 instructions for a 24-number sum). The arithmetic,
// and so every bit of the result, is the same for either.
template <sunindextype N>
sunindextype count(N_Vector v) {
  if constexpr (N > 0) return N;
  else return size(v);
}

// f.template operator()<N>() for the fixed length N = n where one is compiled (1 to 5 columns of 6),
// else N = 0 (any length).
template <class F>
decltype(auto) with_fixed_length(sunindextype n, F&& f) {
  switch (n) {
    case 6: return f.template operator()<6>();
    case 12: return f.template operator()<12>();
    case 18: return f.template operator()<18>();
    case 24: return f.template operator()<24>();
    case 30: return f.template operator()<30>();
    default: return f.template operator()<0>();
  }
}

// The length a vector of these block ends gets kernels compiled for: its own if it holds one problem
// (the block norm needs the blocks' lengths), else 0 (any length).
sunindextype kernel_length(const std::vector<sunindextype>& block_ends) {
  return block_ends.size() == 1 ? block_ends.back() : 0;
}

// Adams' predictor (cvPredict) adds its Nordsieck columns pairwise in place, q (q + 1) / 2 sums a step
// with a = b = 1: that case skips the multiplications (the same values: 1 * x is exact).
template <sunindextype N>
OGIVE_VECTOR_LOOP void linear_sum(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z) {
  const sunindextype n = count<N>(x);
  const sunrealtype *xd = data(x), *yd = data(y);
  sunrealtype* zd = data(z);
  if (a == 1 && b == 1) {
    OGIVE_INDEPENDENT for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] + yd[i];
  } else {
    OGIVE_INDEPENDENT for (sunindextype i = 0; i < n; ++i) zd[i] = a * xd[i] + b * yd[i];
  }
}
template <sunindextype N>
OGIVE_VECTOR_LOOP void constant(sunrealtype c, N_Vector z) {
  sunrealtype* zd = data(z);
  OGIVE_INDEPENDENT for (sunindextype i = 0, n = count<N>(z); i < n; ++i) zd[i] = c;
}
template <sunindextype N>
OGIVE_VECTOR_LOOP void prod(N_Vector x, N_Vector y, N_Vector z) {
  const sunrealtype *xd = data(x), *yd = data(y);
  sunrealtype* zd = data(z);
  OGIVE_INDEPENDENT for (sunindextype i = 0, n = count<N>(x); i < n; ++i) zd[i] = xd[i] * yd[i];
}
template <sunindextype N>
OGIVE_VECTOR_LOOP void div(N_Vector x, N_Vector y, N_Vector z) {
  const sunrealtype *xd = data(x), *yd = data(y);
  sunrealtype* zd = data(z);
  OGIVE_INDEPENDENT for (sunindextype i = 0, n = count<N>(x); i < n; ++i) zd[i] = xd[i] / yd[i];
}
template <sunindextype N>
OGIVE_VECTOR_LOOP void scale(sunrealtype c, N_Vector x, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  OGIVE_INDEPENDENT for (sunindextype i = 0, n = count<N>(x); i < n; ++i) zd[i] = c * xd[i];
}
template <sunindextype N>
OGIVE_VECTOR_LOOP void abs(N_Vector x, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  OGIVE_INDEPENDENT for (sunindextype i = 0, n = count<N>(x); i < n; ++i) zd[i] = std::abs(xd[i]);
}
template <sunindextype N>
OGIVE_VECTOR_LOOP void inv(N_Vector x, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  OGIVE_INDEPENDENT for (sunindextype i = 0, n = count<N>(x); i < n; ++i) zd[i] = 1.0 / xd[i];
}
template <sunindextype N>
OGIVE_VECTOR_LOOP void add_const(N_Vector x, sunrealtype b, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  OGIVE_INDEPENDENT for (sunindextype i = 0, n = count<N>(x); i < n; ++i) zd[i] = xd[i] + b;
}
template <sunindextype N>
sunrealtype dot(N_Vector x, N_Vector y) {
  const sunrealtype *xd = data(x), *yd = data(y);
  sunrealtype sum = 0;
  for (sunindextype i = 0, n = count<N>(x); i < n; ++i) sum += xd[i] * yd[i];
  return sum;
}
template <sunindextype N>
sunrealtype max_norm(N_Vector x) {
  const sunrealtype* xd = data(x);
  sunrealtype m = 0;
  for (sunindextype i = 0, n = count<N>(x); i < n; ++i) m = std::max(m, std::abs(xd[i]));
  return m;
}

// The sum of (x_i w_i)^2 in four interleaved partial sums, added in a fixed order: vectorisable without
// reassociation, so every clone gives the same bits.
template <sunindextype N>
OGIVE_VECTOR_LOOP sunrealtype weighted_squares(const sunrealtype* xd, const sunrealtype* wd, sunindextype length) {
  const sunindextype n = N > 0 ? N : length;
  sunrealtype s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  const sunindextype body = n - n % 4;
  for (sunindextype i = 0; i < body; i += 4) {
    const sunrealtype p0 = xd[i] * wd[i], p1 = xd[i + 1] * wd[i + 1], p2 = xd[i + 2] * wd[i + 2],
                      p3 = xd[i + 3] * wd[i + 3];
    s0 += p0 * p0;
    s1 += p1 * p1;
    s2 += p2 * p2;
    s3 += p3 * p3;
  }
  for (sunindextype i = body; i < n; ++i) s0 += (xd[i] * wd[i]) * (xd[i] * wd[i]);
  return (s0 + s1) + (s2 + s3);
}
template <sunindextype N>
sunrealtype wsqr_sum(N_Vector x, N_Vector w) { return weighted_squares<N>(data(x), data(w), count<N>(x)); }

// CVODE's error test and its iteration's convergence test. Where the state holds several independent
// problems (multiple shooting's segments integrated together), the norm is the largest of theirs, so that
// each is held to the tolerance it would meet alone, never diluted by the others' smaller errors. (A
// fixed length N is only given to a vector of one block.)
template <sunindextype N>
sunrealtype wrms_norm(N_Vector x, N_Vector w) {
  const sunrealtype *xd = data(x), *wd = data(w);
  if constexpr (N > 0) return std::sqrt(weighted_squares<N>(xd, wd, N) / static_cast<sunrealtype>(N));
  sunrealtype largest = 0;
  sunindextype begin = 0;
  for (const sunindextype end : *content(x).block_ends) {
    const sunindextype n = end - begin;  // a block's own length may be a fixed one too (24, 30)
    const sunrealtype squares = with_fixed_length(
        n, [&]<sunindextype M>() { return weighted_squares<M>(xd + begin, wd + begin, n); });
    largest = std::max(largest, squares / static_cast<sunrealtype>(n));
    begin = end;
  }
  return std::sqrt(largest);
}
template <sunindextype N>
sunrealtype min(N_Vector x) {
  const sunrealtype* xd = data(x);
  sunrealtype m = xd[0];
  for (sunindextype i = 1, n = count<N>(x); i < n; ++i) m = std::min(m, xd[i]);
  return m;
}
template <sunindextype N>
OGIVE_VECTOR_LOOP void compare(sunrealtype c, N_Vector x, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  OGIVE_INDEPENDENT for (sunindextype i = 0, n = count<N>(x); i < n; ++i) zd[i] = std::abs(xd[i]) >= c ? 1.0 : 0.0;
}
template <sunindextype N>
sunbooleantype inv_test(N_Vector x, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  bool ok = true;
  for (sunindextype i = 0, n = count<N>(x); i < n; ++i) {
    if (xd[i] == 0) ok = false;
    else zd[i] = 1.0 / xd[i];
  }
  return ok ? SUNTRUE : SUNFALSE;
}
template <sunindextype N>
OGIVE_VECTOR_LOOP int linear_combination(int nvec, sunrealtype* c, N_Vector* X, N_Vector z) {
  sunrealtype* zd = data(z);
  const sunindextype n = count<N>(z);
  // z may alias X[0]; scaling it first, then accumulating, handles both cases.
  const sunrealtype* x0 = data(X[0]);
  OGIVE_INDEPENDENT for (sunindextype i = 0; i < n; ++i) zd[i] = c[0] * x0[i];
  for (int k = 1; k < nvec; ++k) {
    const sunrealtype* xk = data(X[k]);
    OGIVE_INDEPENDENT for (sunindextype i = 0; i < n; ++i) zd[i] += c[k] * xk[i];
  }
  return 0;
}
template <sunindextype N>
OGIVE_VECTOR_LOOP int scale_add_multi(int nvec, sunrealtype* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  const sunrealtype* xd = data(x);
  const sunindextype n = count<N>(x);
  for (int k = 0; k < nvec; ++k) {
    const sunrealtype* yd = data(Y[k]);
    sunrealtype* zd = data(Z[k]);
    OGIVE_INDEPENDENT for (sunindextype i = 0; i < n; ++i) zd[i] = a[k] * xd[i] + yd[i];
  }
  return 0;
}

// CVODE's error weights 1 / (rtol |y_i| + atol), as CVODE computes them for scalar tolerances (the same
// operations in the same order: the same bits), in one loop instead of its five vector calls a step.
// False if a weight would not be positive.
template <sunindextype N>
OGIVE_VECTOR_LOOP bool error_weights(sunrealtype rtol, sunrealtype atol, N_Vector y, N_Vector w) {
  const sunrealtype* yd = data(y);
  sunrealtype* wd = data(w);
  int non_positive = 0;
  OGIVE_INDEPENDENT for (sunindextype i = 0, n = count<N>(y); i < n; ++i) {
    const sunrealtype t = rtol * std::abs(yd[i]) + atol;
    non_positive |= t <= 0;
    wd[i] = 1.0 / t;
  }
  return non_positive == 0;
}

using ErrorWeights = bool (*)(sunrealtype, sunrealtype, N_Vector, N_Vector);
ErrorWeights error_weights_for(N_Vector y) {
  return with_fixed_length(kernel_length(*content(y).block_ends),
                           [&]<sunindextype N>() -> ErrorWeights { return error_weights<N>; });
}

template <sunindextype N>
void set_kernels(N_Vector_Ops ops) {
  ops->nvlinearsum = linear_sum<N>;
  ops->nvconst = constant<N>;
  ops->nvprod = prod<N>;
  ops->nvdiv = div<N>;
  ops->nvscale = scale<N>;
  ops->nvabs = abs<N>;
  ops->nvinv = inv<N>;
  ops->nvaddconst = add_const<N>;
  ops->nvdotprod = dot<N>;
  ops->nvmaxnorm = max_norm<N>;
  ops->nvwrmsnorm = wrms_norm<N>;
  ops->nvmin = min<N>;
  ops->nvcompare = compare<N>;
  ops->nvinvtest = inv_test<N>;
  ops->nvwsqrsumlocal = wsqr_sum<N>;
  ops->nvlinearcombination = linear_combination<N>;
  ops->nvscaleaddmulti = scale_add_multi<N>;
}

// A vector of n zeros with every operation CVODE, its Newton and fixed-point solvers and the block
// linear solver below use.
N_Vector make(std::shared_ptr<const std::vector<sunindextype>> block_ends, SUNContext ctx) {
  const sunindextype n = block_ends->back();
  N_Vector v = N_VNewEmpty(ctx);
  if (!v) return nullptr;
  N_Vector_Ops ops = v->ops;
  ops->nvgetvectorid = get_id;
  ops->nvclone = clone;
  ops->nvcloneempty = clone_empty;
  ops->nvdestroy = destroy;
  ops->nvspace = space;
  ops->nvgetarraypointer = array_pointer;
  ops->nvsetarraypointer = set_array_pointer;
  ops->nvgetlength = length;
  with_fixed_length(kernel_length(*block_ends), [&]<sunindextype N>() { set_kernels<N>(ops); });
  v->content = new Content{n, new sunrealtype[static_cast<std::size_t>(n)](), true, std::move(block_ends)};
  return v;
}

// The fixed-point iteration's update: delta = g - y (CVODE's y_cor), then y = g. The same numbers as
// SUNDIALS' solver's copy, copy and linear sum (1 g + (-1) y_prev: both products are exact).
template <sunindextype N>
OGIVE_VECTOR_LOOP void fixed_point_update(N_Vector g, N_Vector y, N_Vector delta) {
  const sunrealtype* gd = data(g);
  sunrealtype* yd = data(y);
  sunrealtype* dd = data(delta);
  OGIVE_INDEPENDENT for (sunindextype i = 0, n = count<N>(y); i < n; ++i) {
    dd[i] = gd[i] - yd[i];
    yd[i] = gd[i];
  }
}
using FixedPointUpdate = void (*)(N_Vector, N_Vector, N_Vector);
FixedPointUpdate fixed_point_update_for(N_Vector y) {
  return with_fixed_length(kernel_length(*content(y).block_ends),
                           [&]<sunindextype N>() -> FixedPointUpdate { return fixed_point_update<N>; });
}

}  // namespace vector

// ---------------------------------------------------------------------------------------------------
// Adams' nonlinear solver: the plain fixed-point iteration (no Anderson acceleration) of SUNDIALS'
// SUNNonlinSol_FixedPoint with m = 0, step for step (the same calls of CVODE's system function and
// convergence test, the same numbers), with its three vector calls an iteration fused into one loop:
// with Debian's -O0 build of that solver and its vector calls, a raw Adams solve of the equilateral
// arch took 4 % more instructions (callgrind: 490 000 against 471 000 a solve).
namespace fixed_point {

struct Content {
  SUNNonlinSolSysFn system = nullptr;
  SUNNonlinSolConvTestFn test = nullptr;
  void* test_data = nullptr;
  int max_iterations = 3;  // CVODE sets its own (NLS_MAXCOR) when the solver is attached
  int iteration = 0;       // within the current solve
  long iterations = 0, convergence_failures = 0;  // of the last solve (CVODE adds them up)
  N_Vector g = nullptr, delta = nullptr;
  vector::FixedPointUpdate update = nullptr;
};

Content& content(SUNNonlinearSolver s) { return *static_cast<Content*>(s->content); }

SUNNonlinearSolver_Type get_type(SUNNonlinearSolver) { return SUNNONLINEARSOLVER_FIXEDPOINT; }
int initialize(SUNNonlinearSolver s) {
  content(s).iterations = content(s).convergence_failures = 0;
  return content(s).system && content(s).test ? SUN_NLS_SUCCESS : SUN_NLS_MEM_NULL;
}
int solve(SUNNonlinearSolver s, N_Vector, N_Vector y, N_Vector w, sunrealtype tol, sunbooleantype, void* mem) {
  Content& c = content(s);
  c.iterations = c.convergence_failures = 0;
  for (c.iteration = 0; c.iteration < c.max_iterations; ++c.iteration) {
    if (const int flag = c.system(y, c.g, mem); flag != 0) return flag;
    c.update(c.g, y, c.delta);
    ++c.iterations;
    const int flag = c.test(s, y, c.delta, tol, w, c.test_data);
    if (flag == SUN_NLS_SUCCESS) return SUN_NLS_SUCCESS;
    if (flag != SUN_NLS_CONTINUE) {
      ++c.convergence_failures;
      return flag;
    }
  }
  ++c.convergence_failures;
  return SUN_NLS_CONV_RECVR;
}
int free_solver(SUNNonlinearSolver s) {
  if (!s) return SUN_NLS_SUCCESS;
  if (s->content) {
    N_VDestroy(content(s).g);
    N_VDestroy(content(s).delta);
    delete static_cast<Content*>(s->content);
    s->content = nullptr;
  }
  SUNNonlinSolFreeEmpty(s);
  return SUN_NLS_SUCCESS;
}
int set_system(SUNNonlinearSolver s, SUNNonlinSolSysFn f) {
  content(s).system = f;
  return SUN_NLS_SUCCESS;
}
int set_test(SUNNonlinearSolver s, SUNNonlinSolConvTestFn f, void* data) {
  content(s).test = f;
  content(s).test_data = data;
  return SUN_NLS_SUCCESS;
}
int set_max_iterations(SUNNonlinearSolver s, int n) {
  if (n < 1) return SUN_NLS_ILL_INPUT;
  content(s).max_iterations = n;
  return SUN_NLS_SUCCESS;
}
int get_iterations(SUNNonlinearSolver s, long* n) {
  *n = content(s).iterations;
  return SUN_NLS_SUCCESS;
}
int get_iteration(SUNNonlinearSolver s, int* n) {
  *n = content(s).iteration;
  return SUN_NLS_SUCCESS;
}
int get_convergence_failures(SUNNonlinearSolver s, long* n) {
  *n = content(s).convergence_failures;
  return SUN_NLS_SUCCESS;
}

// A solver for vectors like y (nullptr if SUNDIALS cannot allocate).
SUNNonlinearSolver make(N_Vector y, SUNContext ctx) {
  SUNNonlinearSolver s = SUNNonlinSolNewEmpty(ctx);
  if (!s) return nullptr;
  s->ops->gettype = get_type;
  s->ops->initialize = initialize;
  s->ops->solve = solve;
  s->ops->free = free_solver;
  s->ops->setsysfn = set_system;
  s->ops->setctestfn = set_test;
  s->ops->setmaxiters = set_max_iterations;
  s->ops->getnumiters = get_iterations;
  s->ops->getcuriter = get_iteration;
  s->ops->getnumconvfails = get_convergence_failures;
  auto* c = new Content;
  s->content = c;
  c->g = N_VClone(y);
  c->delta = N_VClone(y);
  c->update = vector::fixed_point_update_for(y);
  if (!c->g || !c->delta) {
    free_solver(s);
    return nullptr;
  }
  return s;
}

}  // namespace fixed_point

// ---------------------------------------------------------------------------------------------------
// BDF's Newton matrix I - gamma J. Every column of Y obeys the same ODE, so J is block diagonal with
// identical 6x6 blocks A(theta): the matrix type stores that one block, and the linear solver factors
// it once (Eigen, partial pivoting) and solves every column with it. Debian's -O0 dense 42x42 LU took
// 82 % of a BDF solve.
namespace block {

using Block = Eigen::Matrix<sunrealtype, kStateSize, kStateSize>;

Block& of(SUNMatrix A) { return *static_cast<Block*>(A->content); }

SUNMatrix_ID get_id(SUNMatrix) { return SUNMATRIX_CUSTOM; }
void destroy(SUNMatrix A) {
  if (!A) return;
  delete static_cast<Block*>(A->content);
  A->content = nullptr;
  SUNMatFreeEmpty(A);
}
SUNMatrix clone(SUNMatrix A) {
  SUNMatrix B = SUNMatNewEmpty(A->sunctx);
  if (!B) return nullptr;
  if (SUNMatCopyOps(A, B) != 0) {
    SUNMatFreeEmpty(B);
    return nullptr;
  }
  B->content = new Block(Block::Zero());
  return B;
}
int zero(SUNMatrix A) {
  of(A).setZero();
  return 0;
}
int copy(SUNMatrix A, SUNMatrix B) {
  of(B) = of(A);
  return 0;
}
int scale_add_identity(sunrealtype c, SUNMatrix A) {  // A = c A + I
  of(A) = c * of(A) + Block::Identity();
  return 0;
}
int scale_add(sunrealtype c, SUNMatrix A, SUNMatrix B) {  // A = c A + B
  of(A) = c * of(A) + of(B);
  return 0;
}

SUNMatrix make_matrix(SUNContext ctx) {
  SUNMatrix A = SUNMatNewEmpty(ctx);
  if (!A) return nullptr;
  A->ops->getid = get_id;
  A->ops->clone = clone;
  A->ops->destroy = destroy;
  A->ops->zero = zero;
  A->ops->copy = copy;
  A->ops->scaleaddi = scale_add_identity;
  A->ops->scaleadd = scale_add;
  A->content = new Block(Block::Zero());
  return A;
}

using Factor = Eigen::PartialPivLU<Block>;
Factor& factor_of(SUNLinearSolver S) { return *static_cast<Factor*>(S->content); }

SUNLinearSolver_Type get_type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID get_solver_id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }
int setup(SUNLinearSolver S, SUNMatrix A) {
  factor_of(S).compute(of(A));
  // Partial pivoting never fails; a zero pivot shows as a non-finite inverse estimate.
  return factor_of(S).rcond() > 0 ? SUNLS_SUCCESS : SUNLS_LUFACT_FAIL;
}
int solve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector b, sunrealtype) {
  const sunindextype columns = vector::size(b) / kStateSize;
  Eigen::Map<const Eigen::Matrix<sunrealtype, kStateSize, Eigen::Dynamic>> B(vector::data(b), kStateSize, columns);
  Eigen::Map<Eigen::Matrix<sunrealtype, kStateSize, Eigen::Dynamic>> X(vector::data(x), kStateSize, columns);
  X = factor_of(S).solve(B);
  return SUNLS_SUCCESS;
}
sunindextype last_flag(SUNLinearSolver) { return 0; }
int free_solver(SUNLinearSolver S) {
  if (!S) return 0;
  delete static_cast<Factor*>(S->content);
  S->content = nullptr;
  SUNLinSolFreeEmpty(S);
  return 0;
}

SUNLinearSolver make_solver(SUNContext ctx) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) return nullptr;
  S->ops->gettype = get_type;
  S->ops->getid = get_solver_id;
  S->ops->initialize = initialize;
  S->ops->setup = setup;
  S->ops->solve = solve;
  S->ops->lastflag = last_flag;
  S->ops->free = free_solver;
  S->content = new Factor(kStateSize);
  return S;
}

}  // namespace block

}  // namespace

// The SUNDIALS objects of one kind of integration (method and number of columns): a context, the
// template vector, the solvers and the CVODE memory. Creating them costs as much as a short
// integration, so they are kept per thread and reused (CVodeReInit at every span, tolerances and user
// data set anew at every use): across the segments of multiple shooting, the verifying solve, the
// profile's sampling and the scenes of a sweep. One context per thread, as SUNDIALS asks.
struct Workspace {
  Integrator kind;
  std::vector<int> blocks;  // columns of each independent problem (CvodeIntegrator's blocks)
  // Destroyed in reverse order: CVODE's memory before the solvers and vectors it uses, the context last.
  ContextHandle context;
  VectorHandle y;
  MatrixHandle jacobian;
  LinearSolverHandle linear_solver;
  NonlinearSolverHandle nonlinear_solver;
  CvodeHandle cvode;
};

namespace {

// rhs and jac reach the current use's model through CVODE's user data (CvodeIntegrator::Impl).
std::unique_ptr<Workspace> make_workspace(Integrator kind, const std::vector<int>& blocks, CVRhsFn rhs,
                                          CVLsJacFn jac) {
  auto w = std::make_unique<Workspace>();
  w->kind = kind;
  w->blocks = blocks;
  SUNContext ctx = nullptr;
  check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create");
  w->context.reset(ctx);
  auto block_ends = std::make_shared<std::vector<sunindextype>>();
  sunindextype end = 0;
  for (const int columns : blocks) block_ends->push_back(end += static_cast<sunindextype>(kStateSize) * columns);
  w->y.reset(vector::make(std::move(block_ends), ctx));
  if (!w->y) throw std::runtime_error("N_VNewEmpty failed");
  w->cvode.reset(CVodeCreate(kind == Integrator::adams ? CV_ADAMS : CV_BDF, ctx));
  if (!w->cvode) throw std::runtime_error("CVodeCreate failed");
  void* mem = w->cvode.get();
  check(CVodeInit(mem, rhs, 0.0, w->y.get()), "CVodeInit");
  if (kind == Integrator::adams) {
    w->nonlinear_solver.reset(fixed_point::make(w->y.get(), ctx));
    if (!w->nonlinear_solver) throw std::runtime_error("SUNNonlinSolNewEmpty failed");
    check(CVodeSetNonlinearSolver(mem, w->nonlinear_solver.get()), "CVodeSetNonlinearSolver");
  } else {
    w->jacobian.reset(block::make_matrix(ctx));
    if (!w->jacobian) throw std::runtime_error("SUNMatNewEmpty failed");
    w->linear_solver.reset(block::make_solver(ctx));
    if (!w->linear_solver) throw std::runtime_error("SUNLinSolNewEmpty failed");
    check(CVodeSetLinearSolver(mem, w->linear_solver.get(), w->jacobian.get()), "CVodeSetLinearSolver");
    check(CVodeSetJacFn(mem, jac), "CVodeSetJacFn");
  }
  return w;
}

// The idle workspaces of this thread. At most a few kinds are ever in use at once (multiple shooting's
// 4- and 7-column integrators, the field's 1 column), so the pool stays small.
std::vector<std::unique_ptr<Workspace>>& idle_workspaces() {
  thread_local std::vector<std::unique_ptr<Workspace>> pool;
  return pool;
}

std::unique_ptr<Workspace> take_workspace(Integrator kind, const std::vector<int>& blocks, CVRhsFn rhs,
                                          CVLsJacFn jac) {
  auto& pool = idle_workspaces();
  for (auto it = pool.begin(); it != pool.end(); ++it)
    if ((*it)->kind == kind && (*it)->blocks == blocks) {
      std::unique_ptr<Workspace> w = std::move(*it);
      pool.erase(it);
      return w;
    }
  return make_workspace(kind, blocks, rhs, jac);
}

void return_workspace(std::unique_ptr<Workspace> w) {
  auto& pool = idle_workspaces();
  constexpr std::size_t kMaxIdle = 8;
  if (w && pool.size() < kMaxIdle) pool.push_back(std::move(w));
}

}  // namespace

struct CvodeIntegrator::Impl {
  const OdeSystem& system;
  int columns;
  bool restart;
  std::string last_message;  // CVODE's error text, captured instead of printed
  std::unique_ptr<Workspace> workspace;
  double span_start = 0, span_end = 0;  // the span being integrated
  double first_inside = 0, last_inside = 0;  // the numbers next to its ends, inside it
  double rtol = 0, atol = 0;  // CVODE's, as given (atol > 0)
  vector::ErrorWeights error_weights = nullptr;  // the kernel for the workspace's vector, chosen once

  Impl(const OdeSystem& s, int cols, bool restart_at_breakpoints)
      : system(s), columns(cols), restart(restart_at_breakpoints) {}

  // s moved strictly inside the current span: at a breakpoint the system must see the piece being
  // integrated (a pointed crown's angle, a live load's edge), and CVODE evaluates at the span's ends.
  double inside(double s) const {
    if (!restart || !(span_end > span_start)) return s;
    return std::clamp(s, first_inside, last_inside);
  }

  // CVODE's error weights (CVodeWFtolerances: SUNDIALS' hook for a weight function), the same numbers
  // as its own for scalar tolerances, at a fraction of the cost (vector::error_weights).
  static int weights(N_Vector y, N_Vector w, void* user_data) {
    const auto* self = static_cast<const Impl*>(user_data);
    return self->error_weights(self->rtol, self->atol, y, w) ? 0 : -1;
  }

  static int rhs(sunrealtype s, N_Vector y, N_Vector ydot, void* user_data) {
    const auto* self = static_cast<const Impl*>(user_data);
    const int n = self->columns;
    Eigen::Map<const Matrix> Y(N_VGetArrayPointer(y), kStateSize, n);
    Eigen::Map<Matrix> dY(N_VGetArrayPointer(ydot), kStateSize, n);
    return self->system.rhs(self->inside(s), Y, dY) ? 0 : 1;  // 1: recoverable, CVODE tries a smaller step
  }

  // The Jacobian's one block (the block matrix type above stores only that).
  static int jac(sunrealtype s, N_Vector y, N_Vector, SUNMatrix J, void* user_data, N_Vector, N_Vector,
                 N_Vector) {
    const auto* self = static_cast<const Impl*>(user_data);
    Eigen::Map<const Matrix> Y(N_VGetArrayPointer(y), kStateSize, self->columns);
    block::of(J) = self->system.jacobian_block(self->inside(s), Y);
    return 0;
  }

  static void error_handler(int, const char*, const char* function, char* msg, void* data) {
    static_cast<Impl*>(data)->last_message = std::string(function) + ": " + msg;
  }
};

CvodeIntegrator::CvodeIntegrator(const OdeSystem& system, Integrator kind, double rtol, double atol,
                                 std::int64_t max_steps, int columns, bool restart_at_breakpoints)
    : CvodeIntegrator(system, kind, rtol, atol, max_steps, std::vector<int>{columns}, restart_at_breakpoints) {}

CvodeIntegrator::CvodeIntegrator(const OdeSystem& system, Integrator kind, double rtol, double atol,
                                 std::int64_t max_steps, const std::vector<int>& blocks,
                                 bool restart_at_breakpoints)
    : impl_(std::make_unique<Impl>(system, std::accumulate(blocks.begin(), blocks.end(), 0),
                                   restart_at_breakpoints)) {
  if (!(rtol > 0) || !(atol > 0))
    throw std::invalid_argument("CvodeIntegrator: rtol and atol must be > 0");
  Impl& m = *impl_;
  m.workspace = take_workspace(kind, blocks, &Impl::rhs, &Impl::jac);
  void* mem = m.workspace->cvode.get();
  // Everything a previous use set is set anew: the error handler's and the functions' data, the
  // tolerances, the step limit (the stop time and the history are set by every span's CVodeReInit).
  check(CVodeSetErrHandlerFn(mem, &Impl::error_handler, impl_.get()), "CVodeSetErrHandlerFn");
  check(CVodeSetUserData(mem, impl_.get()), "CVodeSetUserData");
  m.rtol = rtol;
  m.atol = atol;
  m.error_weights = vector::error_weights_for(m.workspace->y.get());
  check(CVodeWFtolerances(mem, &Impl::weights), "CVodeWFtolerances");
  check(CVodeSetMaxNumSteps(mem, static_cast<long>(max_steps)), "CVodeSetMaxNumSteps");
}

CvodeIntegrator::~CvodeIntegrator() {
  if (impl_ && impl_->workspace) return_workspace(std::move(impl_->workspace));
}

std::optional<IntegrationError> CvodeIntegrator::integrate(double s0, const Matrix& Y0,
                                                           std::span<const double> s_out,
                                                           const Observer& observer) {
  Impl& m = *impl_;
  Workspace& w = *m.workspace;
  void* mem = w.cvode.get();
  const int n = m.columns;
  Eigen::Map<Matrix> Y(N_VGetArrayPointer(w.y.get()), kStateSize, n);
  Y = Y0;
  Matrix current = Y0;
  if (s_out.empty()) return std::nullopt;
  const double s_end = s_out.back();
  // Knots: s0, the breakpoints strictly inside (s0, s_end), s_end. Each span is integrated afresh.
  std::vector<double> knots{s0};
  if (m.restart)
    for (double b : m.system.breakpoints())
      if (b > s0 && b < s_end) knots.push_back(b);
  knots.push_back(s_end);

  std::size_t next = 0;
  while (next < s_out.size() && s_out[next] <= s0) observer(next++, current);
  for (std::size_t k = 0; k + 1 < knots.size() && next < s_out.size(); ++k) {
    const double a = knots[k], b = knots[k + 1];
    if (b <= a) continue;
    Y = current;
    m.span_start = a;
    m.span_end = b;
    m.first_inside = std::nextafter(a, b);
    m.last_inside = std::nextafter(b, a);
    check(CVodeReInit(mem, a, w.y.get()), "CVodeReInit");
    check(CVodeSetStopTime(mem, b), "CVodeSetStopTime");
    std::optional<IntegrationError> failure;
    double reached = a;
    // One CVode call to tout; a failure is recorded with the arc length CVODE had reached.
    auto advance = [&](double tout) {
      sunrealtype t = a;
      const int flag = CVode(mem, tout, w.y.get(), &t, CV_NORMAL);
      if (flag < 0) {
        sunrealtype t_now = a;
        check(CVodeGetCurrentTime(mem, &t_now), "CVodeGetCurrentTime");
        failure = IntegrationError{flag, flag_name(flag), t_now, m.last_message};
        return false;
      }
      reached = t;
      current = Y;
      return true;
    };
    while (next < s_out.size() && s_out[next] <= b) {
      if (!advance(s_out[next])) break;
      observer(next++, current);
    }
    // No output left in this span: run to the breakpoint so that the next span starts there.
    if (!failure && reached < b) advance(b);
    // Counters restart with every CVodeReInit: collect them span by span.
    long steps = 0, rhs = 0, etf = 0, jacs = 0, ncf = 0;
    check(CVodeGetNumSteps(mem, &steps), "CVodeGetNumSteps");
    check(CVodeGetNumRhsEvals(mem, &rhs), "CVodeGetNumRhsEvals");
    check(CVodeGetNumErrTestFails(mem, &etf), "CVodeGetNumErrTestFails");
    check(CVodeGetNumNonlinSolvConvFails(mem, &ncf), "CVodeGetNumNonlinSolvConvFails");
    if (w.jacobian) check(CVodeGetNumJacEvals(mem, &jacs), "CVodeGetNumJacEvals");
    stats_.steps += steps;
    stats_.rhs_evaluations += rhs;
    stats_.error_test_failures += etf;
    stats_.jacobian_evaluations += jacs;
    stats_.convergence_failures += ncf;
    if (failure) return failure;
  }
  return std::nullopt;
}

}  // namespace ogive
