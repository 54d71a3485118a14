#pragma once
// Owen-scrambled Sobol points, progressive: point i of a 2D pattern is the same whatever the
// sample count, and any first 2^k points of a pattern are stratified in every elementary
// interval of area 2^-k (a (0, 2)-sequence in base 2), with nested uniform scrambling (Owen 1995)
// hashed as Burley (2020, "Practical Hash-based Owen Scrambling") describes: the index is
// scrambled too, so that patterns of different seeds are decorrelated.

#include <cstdint>

namespace raylab {

constexpr uint32_t reverseBits(uint32_t x) {
    x = ((x >> 1) & 0x55555555U) | ((x & 0x55555555U) << 1);
    x = ((x >> 2) & 0x33333333U) | ((x & 0x33333333U) << 2);
    x = ((x >> 4) & 0x0f0f0f0fU) | ((x & 0x0f0f0f0fU) << 4);
    x = ((x >> 8) & 0x00ff00ffU) | ((x & 0x00ff00ffU) << 8);
    return (x >> 16) | (x << 16);
}

// A permutation of 32-bit values in which bit k of the result depends only on bits 0..k of x
// and on the seed (additions, odd multiplications and x ^= x * even all keep that order).
constexpr uint32_t lowToHighPermutation(uint32_t x, uint32_t seed) {
    x ^= x * 0x3d20adeaU;
    x += seed;
    x *= (seed >> 16) | 1U;
    x ^= x * 0x05526c56U;
    x ^= x * 0x53a22864U;
    return x;
}

// Nested uniform scrambling of a binary fraction x / 2^32: each bit is flipped depending only on
// the bits above it, so intervals map to intervals of the same size and stratification holds.
constexpr uint32_t owenScramble(uint32_t x, uint32_t seed) {
    return reverseBits(lowToHighPermutation(reverseBits(x), seed));
}

// The first two dimensions of Sobol's sequence, as 32-bit binary fractions: the van der Corput
// sequence, and the dimension whose generator matrix is Pascal's triangle mod 2.
constexpr uint32_t sobolDimension0(uint32_t index) { return reverseBits(index); }

// The reference form of dimension 1: the XOR of the matrix's columns for the index's set bits.
constexpr uint32_t sobolDimension1Reference(uint32_t index) {
    uint32_t result = 0;
    for (uint32_t v = 1U << 31; index != 0; index >>= 1, v ^= v >> 1) {
        if (index & 1U) {
            result ^= v;
        }
    }
    return result;
}

namespace detail {
// Dimension 1 of every value of each byte of the index (the matrix is linear over XOR), so that
// a full 32-bit index (scrambled indices are) costs four loads instead of 32 branches; and the
// same with the result's bits reversed (scrambling works on reversed bits).
struct SobolDimension1Tables {
    uint32_t byte[4][256];
    uint32_t reversedByte[4][256];
    constexpr SobolDimension1Tables() : byte{}, reversedByte{} {
        for (uint32_t b = 0; b < 4; ++b) {
            for (uint32_t v = 0; v < 256; ++v) {
                byte[b][v] = sobolDimension1Reference(v << (8 * b));
                reversedByte[b][v] = reverseBits(byte[b][v]);
            }
        }
    }
};
inline constexpr SobolDimension1Tables kSobolDimension1Tables;
} // namespace detail

constexpr uint32_t sobolDimension1(uint32_t index) {
    const auto& t = detail::kSobolDimension1Tables.byte;
    return t[0][index & 0xffU] ^ t[1][(index >> 8) & 0xffU] ^ t[2][(index >> 16) & 0xffU] ^
           t[3][index >> 24];
}

// reverseBits(sobolDimension1(index)), without reversing.
constexpr uint32_t reversedSobolDimension1(uint32_t index) {
    const auto& t = detail::kSobolDimension1Tables.reversedByte;
    return t[0][index & 0xffU] ^ t[1][(index >> 8) & 0xffU] ^ t[2][(index >> 16) & 0xffU] ^
           t[3][index >> 24];
}

} // namespace raylab
