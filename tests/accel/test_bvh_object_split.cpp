// The object split's SAH sweep (core/bvh/build/bvh_build_object_split.h) against a plain
// reference that costs every plane of every axis: the same split, bit for bit, for nodes of a
// few references (most of their bins empty) up to many.

#include "core/bvh/build/bvh_build_object_split.h"

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

} // namespace
} // namespace raylab
