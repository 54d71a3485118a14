#pragma once
// Exact, order-independent sums of float samples, so that a picture whose samples were added in
// parts (sample ranges rendered on different machines, merged later) has the same sums, bit for
// bit, as the picture rendered in one go. Float addition rounds differently in every order;
// integer addition does not.
//
// A FixedSum is a value times 2^64 in a signed 128-bit integer: 63 integer bits and 64 fraction
// bits. toFixed(x) is exact for every float with 2^-40 <= |x| < 2^31 (2^-40 is about 9e-13
// W/m^2): the bits of smaller values below 2^-63 are dropped, larger values are clamped to
// +-2^31, NaN counts as 0. Sums of up to 2^32 samples (the most a film counts) cannot overflow.
// fromFixed of one sample's toFixed is that sample exactly (representable(x) says when it is x
// itself), so one-sample pictures are unchanged.

#include <cstdint>

namespace raylab {

__extension__ typedef __int128 FixedSum;
__extension__ typedef unsigned __int128 FixedSumBits;

inline constexpr float kFixedSampleLimit = 0x1p31f;

// Whether toFixed(x) holds x exactly.
inline bool representable(float x) {
    const float magnitude = __builtin_fabsf(x);
    return (magnitude >= 0x1p-40f && magnitude < kFixedSampleLimit) || x == 0.0f;
}

inline FixedSum toFixed(float x) {
    const float magnitude = __builtin_fabsf(x);
    // The usual case, 2^-28 <= |x| < 2^11 (or 0): x * 2^52 is an integer below 2^63, exact in a
    // double; then 12 more fraction bits of zeros.
    if ((magnitude >= 0x1p-28f && magnitude < 0x1p11f) || x == 0.0f) {
        const auto scaled = static_cast<int64_t>(static_cast<double>(x) * 0x1p52);
        return static_cast<FixedSum>(scaled) * 4096;
    }
    if (!(magnitude < kFixedSampleLimit)) {
        return x != x ? 0 : static_cast<FixedSum>(x > 0.0f ? 1 : -1) << 95;
    }
    // x = whole + fraction, both exact in float, |fraction| < 1; the fraction's bits below 2^-63
    // are truncated.
    const auto wholeBits = static_cast<int64_t>(x); // truncated towards 0
    const float fraction = x - static_cast<float>(wholeBits);
    const auto fractionBits = static_cast<int64_t>(fraction * 0x1p63f);
    return static_cast<FixedSum>(wholeBits) * (static_cast<FixedSum>(1) << 64) +
           static_cast<FixedSum>(fractionBits) * 2;
}

// The sum as a double: its magnitude's integer and fraction words converted and added, the same
// operations for every sum (deterministic), exact when the magnitude has at most 53 significant
// bits (so for every single sample toFixed made).
inline double fromFixed(FixedSum s) {
    const bool negative = s < 0;
    const FixedSumBits magnitude =
        negative ? -static_cast<FixedSumBits>(s) : static_cast<FixedSumBits>(s);
    const auto whole = static_cast<int64_t>(magnitude >> 64); // < 2^63
    const auto halfFraction = static_cast<int64_t>(static_cast<uint64_t>(magnitude) >> 1);
    const double value = static_cast<double>(whole) + static_cast<double>(halfFraction) * 0x1p-63;
    return negative ? -value : value;
}

// What one sample x becomes in a film: x when representable, else fromFixed(toFixed(x)).
inline float asStored(float x) {
    return representable(x) ? x : static_cast<float>(fromFixed(toFixed(x)));
}

} // namespace raylab
