#pragma once
// Lanes<W>: W doubles that every arithmetic operation treats at once, so that
// one kernel written for a scalar type T runs as T = double (one evaluation)
// or T = Lanes<W> (W evaluations side by side, which the compiler turns into
// packed SIMD instructions). Branches become selections: a comparison gives
// a mask (bool for double, LaneMask<W> for lanes) and select(mask, a, b)
// picks per lane. Also the 3-vectors and 3×3 matrices of such a T that the
// batched 3×3 kernels need.
#include <algorithm>
#include <cmath>

namespace sinew {

/// The lanes of the batched kernels: what fits one SIMD register with AVX
/// (four doubles), else with SSE2 (two).
#if defined(__AVX__)
constexpr int kSimdLanes = 4;
#else
constexpr int kSimdLanes = 2;
#endif

/// GCC's and Clang's vector extension: W doubles in one value, whose
/// arithmetic compiles to packed SIMD instructions (split into several when W
/// is wider than the target's registers).
template <int W>
struct VectorTypes {
    typedef double Double __attribute__((vector_size(8 * W)));
    typedef long long Mask __attribute__((vector_size(8 * W)));
};
template <int W>
using DoubleVector = typename VectorTypes<W>::Double;
template <int W>
using MaskVector = typename VectorTypes<W>::Mask;

/// Per-lane truth values (all bits set where true), from comparing Lanes.
template <int W>
struct LaneMask {
    MaskVector<W> bits;

    friend LaneMask operator&&(const LaneMask& a, const LaneMask& b) { return {a.bits & b.bits}; }
    friend LaneMask operator||(const LaneMask& a, const LaneMask& b) { return {a.bits | b.bits}; }
    friend LaneMask operator!(const LaneMask& a) { return {~a.bits}; }
    friend bool any(const LaneMask& mask)
    {
        bool r = false;
        for (int k = 0; k < W; ++k)
            r = r || mask.bits[k] != 0;
        return r;
    }
};

template <int W>
struct Lanes {
    DoubleVector<W> v;

    Lanes() = default;
    Lanes(double value)  // NOLINT: a double broadcast to every lane, as in scalar code
        : v(value - DoubleVector<W>{})
    {
    }
    static Lanes of(const DoubleVector<W>& value)
    {
        Lanes r;
        r.v = value;
        return r;
    }

    double lane(int k) const { return v[k]; }
    void set_lane(int k, double value) { v[k] = value; }

    friend Lanes operator+(const Lanes& a, const Lanes& b) { return of(a.v + b.v); }
    friend Lanes operator-(const Lanes& a, const Lanes& b) { return of(a.v - b.v); }
    friend Lanes operator*(const Lanes& a, const Lanes& b) { return of(a.v * b.v); }
    friend Lanes operator/(const Lanes& a, const Lanes& b) { return of(a.v / b.v); }
    friend Lanes operator-(const Lanes& a) { return of(-a.v); }
    Lanes& operator+=(const Lanes& b) { return *this = *this + b; }
    Lanes& operator-=(const Lanes& b) { return *this = *this - b; }

    friend LaneMask<W> operator<(const Lanes& a, const Lanes& b) { return {a.v < b.v}; }
    friend LaneMask<W> operator<=(const Lanes& a, const Lanes& b) { return {a.v <= b.v}; }
    friend LaneMask<W> operator>(const Lanes& a, const Lanes& b) { return {a.v > b.v}; }
    friend LaneMask<W> operator>=(const Lanes& a, const Lanes& b) { return {a.v >= b.v}; }

    friend Lanes sqrt(const Lanes& a)
    {
        Lanes r;
        for (int k = 0; k < W; ++k)
            r.v[k] = __builtin_sqrt(a.v[k]);
        return r;
    }
    /// |a|: the sign bit cleared.
    friend Lanes abs(const Lanes& a) { return of(DoubleVector<W>(bits(a) & ~sign_bit())); }
    /// |magnitude| with the sign bit of `sign`.
    friend Lanes copysign(const Lanes& magnitude, const Lanes& sign)
    {
        return of(DoubleVector<W>((bits(magnitude) & ~sign_bit()) | (bits(sign) & sign_bit())));
    }
    /// b where b < a, else a (std::min's choice, also for NaN).
    friend Lanes min(const Lanes& a, const Lanes& b) { return of(b.v < a.v ? b.v : a.v); }
    /// b where a < b, else a (std::max's choice, also for NaN).
    friend Lanes max(const Lanes& a, const Lanes& b) { return of(a.v < b.v ? b.v : a.v); }
    friend Lanes select(const LaneMask<W>& mask, const Lanes& a, const Lanes& b)
    {
        return of(mask.bits ? a.v : b.v);
    }

private:
    /// The lanes' bits (a cast between vector types of one size keeps the bits).
    static MaskVector<W> bits(const Lanes& a) { return MaskVector<W>(a.v); }
    static MaskVector<W> sign_bit() { return MaskVector<W>{} + static_cast<long long>(1ULL << 63); }
};

/// destinations[k][j] (+= when `add`, else =) values[j].lane(k) for j < count
/// and k < lanes ≤ W: W results of one kernel run in lanes, each to its own
/// array. The values are transposed W entries at a time in registers, so that
/// every destination receives whole vectors.
template <bool add, int W>
void unpack_lanes_to(const Lanes<W>* values, int count, double* const* destinations, int lanes)
{
    using Vector = DoubleVector<W>;
    int j = 0;
    for (; j + W <= count; j += W) {
        Vector rows[W];
        for (int r = 0; r < W; ++r)
            rows[r] = values[j + r].v;
        Vector columns[W];  // columns[k][r] = rows[r][k]
        // __builtin_shufflevector (GCC 12 and Clang): constant lane indices
        // into the concatenation of its two arguments.
        if constexpr (W == 4) {
            const Vector t0 = __builtin_shufflevector(rows[0], rows[1], 0, 4, 2, 6);
            const Vector t1 = __builtin_shufflevector(rows[0], rows[1], 1, 5, 3, 7);
            const Vector t2 = __builtin_shufflevector(rows[2], rows[3], 0, 4, 2, 6);
            const Vector t3 = __builtin_shufflevector(rows[2], rows[3], 1, 5, 3, 7);
            columns[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
            columns[1] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
            columns[2] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
            columns[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
        } else if constexpr (W == 2) {
            columns[0] = __builtin_shufflevector(rows[0], rows[1], 0, 2);
            columns[1] = __builtin_shufflevector(rows[0], rows[1], 1, 3);
        } else {
            for (int k = 0; k < W; ++k)
                for (int r = 0; r < W; ++r)
                    columns[k][r] = rows[r][k];
        }
        for (int k = 0; k < lanes; ++k) {
            Vector result = columns[k];
            if constexpr (add) {
                Vector sum;
                __builtin_memcpy(&sum, destinations[k] + j, sizeof(Vector));
                result += sum;
            }
            __builtin_memcpy(destinations[k] + j, &result, sizeof(Vector));
        }
    }
    for (; j < count; ++j)
        for (int k = 0; k < lanes; ++k)
            destinations[k][j] = add ? destinations[k][j] + values[j].lane(k) : values[j].lane(k);
}

/// destinations[k][j] += values[j].lane(k) (unpack_lanes_to).
template <int W>
void add_lanes_to(const Lanes<W>* values, int count, double* const* destinations, int lanes)
{
    unpack_lanes_to<true>(values, count, destinations, lanes);
}

/// destinations[k][j] = values[j].lane(k) (unpack_lanes_to).
template <int W>
void copy_lanes_to(const Lanes<W>* values, int count, double* const* destinations, int lanes)
{
    unpack_lanes_to<false>(values, count, destinations, lanes);
}

/// The scalar counterparts, so that a kernel template reads the same for
/// T = double.
namespace lanes {
using std::abs;
using std::copysign;
using std::sqrt;
inline double min(double a, double b) { return std::min(a, b); }
inline double max(double a, double b) { return std::max(a, b); }
inline double select(bool mask, double a, double b) { return mask ? a : b; }
inline bool any(bool mask) { return mask; }
} // namespace lanes

/// A 3-vector of T.
template <typename T>
struct Vector3 {
    T x[3];

    T& operator[](int i) { return x[i]; }
    const T& operator[](int i) const { return x[i]; }
    friend Vector3 operator+(const Vector3& a, const Vector3& b) { return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}}; }
    friend Vector3 operator-(const Vector3& a, const Vector3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
    friend Vector3 operator*(const T& s, const Vector3& a) { return {{s * a[0], s * a[1], s * a[2]}}; }
    Vector3& operator-=(const Vector3& b) { return *this = *this - b; }
    Vector3& operator+=(const Vector3& b) { return *this = *this + b; }
};

template <typename T>
T dot(const Vector3<T>& a, const Vector3<T>& b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <typename T>
Vector3<T> cross(const Vector3<T>& a, const Vector3<T>& b)
{
    return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

template <typename Mask, typename T>
Vector3<T> select(const Mask& mask, const Vector3<T>& a, const Vector3<T>& b)
{
    using lanes::select;
    return {{select(mask, a[0], b[0]), select(mask, a[1], b[1]), select(mask, a[2], b[2])}};
}

/// A 3×3 matrix of T as its three columns.
template <typename T>
struct Matrix3 {
    Vector3<T> col[3];

    T& operator()(int i, int j) { return col[j][i]; }
    const T& operator()(int i, int j) const { return col[j][i]; }
};

/// M v.
template <typename T>
Vector3<T> operator*(const Matrix3<T>& M, const Vector3<T>& v)
{
    return v[0] * M.col[0] + v[1] * M.col[1] + v[2] * M.col[2];
}

} // namespace sinew
