#include "methods/cvode/vector_kernels.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace ogive::cvode::vector {

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
// emits no overlap checks (a large share of a short loop's instructions).
#if defined(__GNUC__) && !defined(__clang__)
#define OGIVE_INDEPENDENT _Pragma("GCC ivdep")
#else
#define OGIVE_INDEPENDENT
#endif

// Every loop below is a template on the vector's length N, fixed at compile time for the lengths that
// shooting uses (1 to 5 columns of 6) and 0 for any other (then read from the vector): a fixed length
// turns a loop of 24 numbers into six AVX2 instructions with no trip-count logic, which for vectors this
// short is most of a kernel's cost. The arithmetic, and so every bit of the result, is the same for either.
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
FixedPointUpdate fixed_point_update_for(N_Vector y) {
  return with_fixed_length(kernel_length(*content(y).block_ends),
                           [&]<sunindextype N>() -> FixedPointUpdate { return fixed_point_update<N>; });
}

}  // namespace ogive::cvode::vector
