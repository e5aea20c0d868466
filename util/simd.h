#pragma once
// luxgrid's one SIMD header: the four-lane types, their helpers, a polynomial evaluator and the
// one macro for function multiversioning. Each numeric kernel is written once, as a template over
// its value type T: `double` (one value) or `D4` (four doubles, the lanes of one computation),
// the way Mitsuba 3 writes each plugin once over its Float [Jakob2022] and OpenImageIO keeps its
// SIMD types and helpers in one header (simd.h). Each helper below performs on every lane the
// IEEE operation its scalar overload performs on one value, so a kernel's scalar and four-lane
// instantiations give the same bits (tests/util/simd_test.cpp and one test per kernel); the
// build pins -ffp-contract=off (CMakeLists.txt) so that no compiler fuses a multiply and an add
// in one instantiation or one clone and not in another.
//
// The lane types are GCC's vector extension (clang has it too): one AVX2 register in a function
// compiled for AVX2, two SSE2 ones in the baseline build. Passing such a vector by value between
// functions compiled for different targets changes the calling convention, so:
// - every helper here and every kernel template is [[gnu::always_inline]] (LUXGRID_LANE): never
//   called, always part of the function it is used in, compiled for that function's target;
// - a multiversioned entry point (LUXGRID_MULTIVERSION) takes pointers, references and scalars,
//   never a lane vector by value.
// GCC and clang still warn, at every inline function that takes or returns a vector, that the
// convention would change for a call; there is no call, so the warning is silenced for the files
// that include this (clang's error for a call between targets stays: the rule above avoids it).
#include <bit>
#include <cmath>
#include <cstddef>
#include <type_traits>

#pragma GCC diagnostic ignored "-Wpsabi"  // (clang reads it too)

// A helper or a kernel over lanes: inlined into its caller, always (see above).
#define LUXGRID_LANE [[gnu::always_inline]] inline

namespace luxgrid::simd {

// Four doubles, and four lane masks (-1 true, 0 false: what a comparison of D4s gives).
using D4 = double __attribute__((vector_size(32)));
using L4 = long long __attribute__((vector_size(32)));
inline constexpr int kLanes = 4;

// The sign bit of a double (a vector cast reinterprets a lane's bits).
inline constexpr long long kSignBit = static_cast<long long>(0x8000000000000000ULL);

// The mask type of a value type: what its comparisons give.
template <class T>
struct LaneTraits;
template <>
struct LaneTraits<double> {
  using Mask = bool;
};
template <>
struct LaneTraits<D4> {
  using Mask = L4;
};
template <class T>
using Mask = typename LaneTraits<T>::Mask;

// x in every lane.
template <class T>
LUXGRID_LANE T splat(double x) {
  if constexpr (std::is_same_v<T, double>)
    return x;
  else
    return T{x, x, x, x};
}

// The lanes f(0), f(1), f(2), f(3) (f(0) for one value): loads from arrays of structures.
template <class T, class F>
LUXGRID_LANE T make(const F& f) {
  if constexpr (std::is_same_v<T, double>)
    return f(0);
  else
    return T{f(0), f(1), f(2), f(3)};
}

// p[0..lanes) as lanes, and back.
template <class T>
LUXGRID_LANE T load(const double* p) {
  return make<T>([p](int l) { return p[l]; });
}
LUXGRID_LANE void store(double x, double* p) { *p = x; }
LUXGRID_LANE void store(const D4& x, double* p) {
  for (int l = 0; l < kLanes; ++l) p[l] = x[l];
}

// m ? a : b, lane by lane.
LUXGRID_LANE double select(bool m, double a, double b) { return m ? a : b; }
LUXGRID_LANE D4 select(const L4& m, const D4& a, const D4& b) { return m ? a : b; }

// std::min and std::max as the standard defines them ((b < a) ? b : a, (a < b) ? b : a), which
// fixes what a NaN or a pair of zeros gives.
template <class T>
LUXGRID_LANE T min(const T& a, const T& b) {
  return select(b < a, b, a);
}
template <class T>
LUXGRID_LANE T max(const T& a, const T& b) {
  return select(a < b, b, a);
}

// |x| (std::abs: the sign bit cleared, NaN too) and std::sqrt, lane by lane.
LUXGRID_LANE double abs(double x) { return std::abs(x); }
LUXGRID_LANE D4 abs(const D4& x) { return (D4)((L4)x & ~kSignBit); }
LUXGRID_LANE double sqrt(double x) { return std::sqrt(x); }
LUXGRID_LANE D4 sqrt(const D4& x) {
  return D4{std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])};
}
// std::signbit, lane by lane (-0 and negative NaNs included).
LUXGRID_LANE bool signbit(double x) { return std::signbit(x); }
LUXGRID_LANE L4 signbit(const D4& x) { return ((L4)x & kSignBit) != 0; }

// Not m, m and n, m or n, lane by lane.
LUXGRID_LANE bool logical_not(bool m) { return !m; }
LUXGRID_LANE L4 logical_not(const L4& m) { return ~m; }
LUXGRID_LANE bool logical_and(bool m, bool n) { return m && n; }
LUXGRID_LANE L4 logical_and(const L4& m, const L4& n) { return m & n; }
LUXGRID_LANE bool logical_or(bool m, bool n) { return m || n; }
LUXGRID_LANE L4 logical_or(const L4& m, const L4& n) { return m | n; }

// Whether the mask holds in every lane.
LUXGRID_LANE bool all(bool m) { return m; }
LUXGRID_LANE bool all(const L4& m) { return m[0] && m[1] && m[2] && m[3]; }

// The lanes added in a fixed order, from +0 as a scalar loop `sum += v[k]` adds them:
// (((0 + v0) + v1) + v2) + v3.
LUXGRID_LANE double sum_in_order(double v) { return 0.0 + v; }
LUXGRID_LANE double sum_in_order(const D4& v) {
  double s = 0.0;
  for (int l = 0; l < kLanes; ++l) s += v[l];
  return s;
}

// A 3-vector of values of T (four vectors for D4), with glm's dot and cross products in glm's
// order of operations, so that a kernel over V3<double> gives glm's bits.
template <class T>
struct V3 {
  T x, y, z;
};
template <class T>
LUXGRID_LANE V3<T> operator-(const V3<T>& a, const V3<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
LUXGRID_LANE T dot(const V3<T>& a, const V3<T>& b) {
  return (a.x * b.x + a.y * b.y) + a.z * b.z;
}
template <class T>
LUXGRID_LANE V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}
template <class T>
LUXGRID_LANE T length(const V3<T>& a) {
  return sqrt(dot(a, a));
}

// The polynomial c[0] + c[1] x + ... + c[N - 1] x^(N - 1), in Estrin's form: pairs
// c[i] + x c[i + 1], then pairs of pairs with x^2, then with x^4, ...: independent products where
// Horner's form is a chain of N - 1 dependent ones [Knuth1997, 4.6.4]. The order of every
// operation is fixed by N alone, so any T gives the same bits.
namespace detail {
template <std::size_t B, std::size_t N, class T, std::size_t M, std::size_t K>
LUXGRID_LANE T estrin_part(const T (&powers)[M], const double (&c)[K]) {
  if constexpr (N == 1) {
    return splat<T>(c[B]);
  } else if constexpr (N == 2) {
    return c[B] + powers[0] * c[B + 1];
  } else {
    constexpr std::size_t h = std::bit_floor(N - 1);  // the low part's length, a power of 2
    return estrin_part<B, h>(powers, c) +
           powers[std::countr_zero(h)] * estrin_part<B + h, N - h>(powers, c);
  }
}
}  // namespace detail

template <class T, std::size_t N>
LUXGRID_LANE T estrin(const T& x, const double (&c)[N]) {
  static_assert(N >= 1);
  constexpr std::size_t kPowers = N > 1 ? std::bit_width(N - 1) : 1;  // x, x^2, x^4, ...
  T powers[kPowers];
  powers[0] = x;
  for (std::size_t p = 1; p < kPowers; ++p) powers[p] = powers[p - 1] * powers[p - 1];
  return detail::estrin_part<0, N>(powers, c);
}

// The same polynomial in Horner's form, c[0] + x (c[1] + x (c[2] + ...)): fewer operations, one
// chain.
template <class T, std::size_t N>
LUXGRID_LANE T horner(const T& x, const double (&c)[N]) {
  T r = splat<T>(c[N - 1]);
  for (std::size_t i = N - 1; i-- > 0;) r = c[i] + x * r;
  return r;
}

// The sum of a[j] x[j] over j in [b, e) (a's floats widened to double) in four independent
// partial sums, the lanes of a D4: a single sum is one long chain of dependent additions, which
// (not the memory) limits a long dot product. Lane l adds the terms j = b + l + 4 i in order, the
// tail adds to lane 0, and the result is (s0 + s1) + (s2 + s3): the same bits as four scalar
// sums in that order.
LUXGRID_LANE double dot_in_four_sums(const float* a, const double* x, std::size_t b,
                                     std::size_t e) {
  D4 s = {0.0, 0.0, 0.0, 0.0};
  std::size_t j = b;
  for (; j + 4 <= e; j += 4) {
    const D4 r = {static_cast<double>(a[j]), static_cast<double>(a[j + 1]),
                  static_cast<double>(a[j + 2]), static_cast<double>(a[j + 3])};
    s += r * load<D4>(x + j);
  }
  double s0 = s[0];
  for (; j < e; ++j) s0 += static_cast<double>(a[j]) * x[j];
  return (s0 + s[1]) + (s[2] + s[3]);
}

// Whether this processor runs AVX2, asked once.
inline bool cpu_has_avx2() {
#if defined(__x86_64__) || defined(__i386__)
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
#else
  return false;
#endif
}

}  // namespace luxgrid::simd

// LUXGRID_MULTIVERSION(ret, name, (params), (args), kernel) defines three functions (where GCC's
// target_clones would make clones that cannot be called by name, and only in GCC):
//   ret name_avx2(params)     kernel(args) compiled for AVX2,
//   ret name_default(params)  kernel(args) compiled for the baseline (SSE2 on x86-64),
//   ret name(params)          the one of the two this processor runs, chosen once.
// kernel is a LUXGRID_LANE template (or inline function), so each of the first two is a whole
// copy of it for its target. The first two can be called by name (the tests call both: a kernel
// must give the same bits in each); declare the three in a header with
// LUXGRID_MULTIVERSION_DECLARE. This is the one place where luxgrid names a target: other
// targets (AVX-512) would be one more function here. Not x86: both are the baseline.
#if defined(__x86_64__) || defined(__i386__)
#define LUXGRID_TARGET_AVX2 [[gnu::target("avx2")]]
#else
#define LUXGRID_TARGET_AVX2
#endif
#define LUXGRID_MULTIVERSION(ret, name, params, args, kernel)                        \
  LUXGRID_TARGET_AVX2 ret name##_avx2 params { return kernel args; }                 \
  ret name##_default params { return kernel args; }                                  \
  ret name params {                                                                  \
    return ::luxgrid::simd::cpu_has_avx2() ? name##_avx2 args : name##_default args; \
  }
#define LUXGRID_MULTIVERSION_DECLARE(ret, name, params) \
  ret name##_avx2 params;                               \
  ret name##_default params;                            \
  ret name params;
