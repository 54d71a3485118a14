// The object split's SAH sweep (core/bvh/build/bvh_build_object_split.h) against a plain
// reference that costs every plane of every axis: the same split, bit for bit, for nodes of a
// few references (most of their bins empty) up to many.

#include "core/bvh/build/bvh_build_object_split.h"

#include <algorithm>
#include <cstring>
#include <gtest/gtest.h>
#include <random>

namespace raylab {
namespace {

// Every plane k (between bins k - 1 and k) of every splittable axis, costed as A(left) N(left)
// + A(right) N(right); the earliest plane of the cheapest cost, on the lowest such axis.
ObjectSplit referenceSplit(const BinSet& bins, uint32_t count, const ObjectSplit& frame) {
    ObjectSplit best = frame;
    for (int a = 0; a < 3; ++a) {
        if (!(frame.scale[a] > 0.0f)) {
            continue;
        }
        for (int k = 1; k < frame.bins; ++k) {
            Aabb left, right;
            uint32_t nLeft = 0, nRight = 0;
            for (int b = 0; b < frame.bins; ++b) {
                (b < k ? left : right).extend(bins.box[a][b].toAabb());
                (b < k ? nLeft : nRight) += bins.count[a][b];
            }
            if (nLeft == 0 || nLeft >= count) {
                continue;
            }
            const float cost =
                left.area() * static_cast<float>(nLeft) + right.area() * static_cast<float>(nRight);
            if (cost < best.cost) {
                best.cost = cost;
                best.axis = a;
                best.bin = k;
                best.leftCount = nLeft;
                Aabb overlap;
                overlap.lower = glm::max(left.lower, right.lower);
                overlap.upper = glm::min(left.upper, right.upper);
                best.overlapArea = overlap.area();
            }
        }
    }
    return best;
}

TEST(BvhObjectSplit, SweepOfUsedBinsMatchesEveryPlane) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int splits = 0;
    for (int trial = 0; trial < 600; ++trial) {
        const int count = 2 + trial % 40;
        const int bins = trial % 3 == 0 ? 32 : (trial % 3 == 1 ? 16 : 7);
        // Clustered centroids (many empty bins), boxes of varied size.
        RecordVector records;
        const float spread = trial % 2 == 0 ? 1.0f : 0.05f;
        for (int i = 0; i < count; ++i) {
            const glm::vec3 at = i % 4 == 0 ? glm::vec3(unit(rng), unit(rng), unit(rng))
                                            : glm::vec3(0.5f) + spread * glm::vec3(unit(rng));
            const glm::vec3 size = 0.1f * glm::vec3(unit(rng), unit(rng), unit(rng));
            records.push_back({at - size, static_cast<uint32_t>(i), at + size, 0.0f});
        }
        const RecordBounds bounds = boundsOf(records.data(), records.data() + count);
        const ObjectSplit frame = objectBinFrame(bounds.centres.toAabb(), bins);
        BinSet binned;
        binned.reset(bins);
        binRecords(records.data(), records.data() + count, frame.lower, frame.scale, bins, binned);
        const ObjectSplit got = bestObjectSplit(binned, static_cast<uint32_t>(count), frame);
        const ObjectSplit want = referenceSplit(binned, static_cast<uint32_t>(count), frame);
        ASSERT_EQ(got.axis, want.axis) << "trial " << trial;
        splits += got.axis >= 0 ? 1 : 0;
        if (want.axis < 0) {
            continue;
        }
        EXPECT_EQ(got.bin, want.bin) << "trial " << trial;
        EXPECT_EQ(got.cost, want.cost) << "trial " << trial;
        EXPECT_EQ(got.leftCount, want.leftCount) << "trial " << trial;
        EXPECT_EQ(got.overlapArea, want.overlapArea) << "trial " << trial;
        EXPECT_EQ(leftCountOf(binned, got), want.leftCount) << "trial " << trial;
    }
    EXPECT_GT(splits, 500);
}

// The bins of records added one at a time, each to its bin on every axis (binOf).
BinSet binOneByOne(const RecordVector& records, const ObjectSplit& frame) {
    BinSet bins;
    bins.reset(frame.bins);
    for (const PrimRecord& r : records) {
        for (int a = 0; a < 3; ++a) {
            const int b =
                binOf(r.lower[a] + r.upper[a], frame.lower[a], frame.scale[a], frame.bins);
            bins.box[a][b].extend(_mm_loadu_ps(&r.lower.x), _mm_loadu_ps(&r.upper.x));
            ++bins.count[a][b];
        }
    }
    return bins;
}

// Lanes x, y and z of two registers hold the same bits (zeros' signs included).
bool sameBits(__m128 a, __m128 b) {
    alignas(16) float x[4], y[4];
    _mm_store_ps(x, a);
    _mm_store_ps(y, b);
    return std::memcmp(x, y, 3 * sizeof(float)) == 0;
}

// binRecords takes records two at a time and writes a pair that shares a bin once: its bins
// must be those of the records added one by one, bit for bit, whether neighbours share their
// bins on every axis, on some or on none, for odd and even counts, with zeros of both signs.
TEST(BvhObjectSplit, BinsMatchRecordsAddedOneByOne) {
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> cell(0, 3), choice(0, 3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int pairsSharing[4] = {}; // pairs of records binRecords takes together, by axes shared
    for (int trial = 0; trial < 400; ++trial) {
        const int count = 1 + trial % 37;
        const int bins = trial % 2 == 0 ? 16 : 5;
        RecordVector records;
        glm::vec3 at(0.0f);
        for (int i = 0; i < count; ++i) {
            // Mostly a neighbour of the previous record (often in its bins), sometimes a jump;
            // coordinates on a coarse grid, so that equal bounds with zeros of either sign occur.
            if (i == 0 || choice(rng) == 0) {
                at = glm::vec3(static_cast<float>(cell(rng)), static_cast<float>(cell(rng)),
                               static_cast<float>(cell(rng)));
            } else if (choice(rng) == 1) {
                at[choice(rng) % 3] = static_cast<float>(cell(rng));
            }
            glm::vec3 lower = at - 0.25f * static_cast<float>(cell(rng)),
                      upper = at + 0.5f * unit(rng);
            for (int a = 0; a < 3; ++a) {
                if (lower[a] == 0.0f && choice(rng) < 2) {
                    lower[a] = -0.0f;
                }
            }
            records.push_back({lower, static_cast<uint32_t>(i), upper, 0.0f});
        }
        const RecordBounds bounds = boundsOf(records.data(), records.data() + count);
        const ObjectSplit frame = objectBinFrame(bounds.centres.toAabb(), bins);
        for (int i = 0; i + 1 < count; i += 2) {
            int sharedAxes = 0;
            for (int a = 0; a < 3; ++a) {
                const auto binOn = [&](const PrimRecord& r) {
                    return binOf(r.lower[a] + r.upper[a], frame.lower[a], frame.scale[a], bins);
                };
                sharedAxes += binOn(records[i]) == binOn(records[i + 1]) ? 1 : 0;
            }
            ++pairsSharing[sharedAxes];
        }
        BinSet got;
        got.reset(bins);
        binRecords(records.data(), records.data() + count, frame.lower, frame.scale, bins, got);
        const BinSet want = binOneByOne(records, frame);
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < bins; ++b) {
                ASSERT_EQ(got.count[a][b], want.count[a][b]) << "trial " << trial;
                ASSERT_TRUE(sameBits(got.box[a][b].lower, want.box[a][b].lower))
                    << "trial " << trial << " axis " << a << " bin " << b;
                ASSERT_TRUE(sameBits(got.box[a][b].upper, want.box[a][b].upper))
                    << "trial " << trial << " axis " << a << " bin " << b;
            }
        }
    }
    for (int axes = 0; axes <= 3; ++axes) {
        EXPECT_GT(pairsSharing[axes], 200) << "pairs sharing their bins on " << axes << " axes";
    }
}

bool sameBounds(const RecordBounds& a, const RecordBounds& b) {
    return sameBits(a.box.lower, b.box.lower) && sameBits(a.box.upper, b.box.upper) &&
           sameBits(a.centres.lower, b.centres.lower) && sameBits(a.centres.upper, b.centres.upper);
}

// partitionRecords against a plain stable partition by binOf, each side's bounds added in order:
// the same records in the same places and the same bounds, bit for bit, whether neighbouring
// records mostly go the same way (sorted along the axis: the partition's branch loop) or at
// random (shuffled: its select loop), on every axis and for every plane.
TEST(BvhObjectSplit, PartitionIsAStablePartitionInAnyOrder) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_int_distribution<int> grid(-2, 2);
    int cases = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const int count = trial % 3 == 0 ? 15 + trial : 300 + 37 * trial;
        RecordVector records;
        for (int i = 0; i < count; ++i) {
            // Coarse coordinates half the time, so that equal bounds and zeros of both signs
            // occur.
            glm::vec3 at = trial % 2 == 0 ? glm::vec3(unit(rng), unit(rng), unit(rng))
                                          : glm::vec3(static_cast<float>(grid(rng)),
                                                      static_cast<float>(grid(rng)), 0.0f);
            if (trial % 2 != 0 && i % 2 == 0) {
                at.z = -0.0f;
            }
            const glm::vec3 size = 0.2f * glm::abs(glm::vec3(unit(rng), unit(rng), unit(rng)));
            records.push_back({at - size, static_cast<uint32_t>(i), at + size, 0.0f});
        }
        const int axis = trial % 3;
        if (trial % 4 < 2) { // sorted along the axis: long runs on each side
            std::sort(records.begin(), records.end(),
                      [&](const PrimRecord& a, const PrimRecord& b) {
                          return a.centroid()[axis] < b.centroid()[axis];
                      });
        }
        const RecordBounds all = boundsOf(records.data(), records.data() + count);
        ObjectSplit split = objectBinFrame(all.centres.toAabb(), 16);
        if (!(split.scale[axis] > 0.0f)) {
            continue;
        }
        split.axis = axis;
        for (int bin = 1; bin < split.bins; ++bin) {
            split.bin = bin;
            RecordVector wantLeft, wantRight;
            RecordBounds wantLeftBounds, wantRightBounds;
            for (const PrimRecord& r : records) {
                const bool isLeft = binOf(r.lower[axis] + r.upper[axis], split.lower[axis],
                                          split.scale[axis], split.bins) < bin;
                (isLeft ? wantLeft : wantRight).push_back(r);
                (isLeft ? wantLeftBounds : wantRightBounds).add(r);
            }
            RecordVector out(records.size());
            RecordBounds leftBounds, rightBounds;
            partitionRecords(records.data(), records.data() + count, split, out.data(),
                             out.data() + wantLeft.size(), leftBounds, rightBounds);
            ASSERT_EQ(
                std::memcmp(out.data(), wantLeft.data(), wantLeft.size() * sizeof(PrimRecord)), 0)
                << "trial " << trial << " bin " << bin;
            ASSERT_EQ(std::memcmp(out.data() + wantLeft.size(), wantRight.data(),
                                  wantRight.size() * sizeof(PrimRecord)),
                      0)
                << "trial " << trial << " bin " << bin;
            ASSERT_TRUE(sameBounds(leftBounds, wantLeftBounds)) << "trial " << trial;
            ASSERT_TRUE(sameBounds(rightBounds, wantRightBounds)) << "trial " << trial;
            ++cases;
        }
    }
    EXPECT_GT(cases, 600);
}

} // namespace
} // namespace raylab
