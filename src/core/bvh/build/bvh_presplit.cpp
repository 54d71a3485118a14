#include "bvh/build/bvh_presplit.h"

#include "bvh/build/bvh_clip.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace raylab {

namespace {

// Box surface not explained by the triangle itself (a flat triangle's box has at least twice
// its area): the part of the box that rays hit without hitting the triangle.
float waste(const Triangle& t, const Aabb& box) {
    const float triangleArea = 0.5f * glm::length(glm::cross(t.v1 - t.v0, t.v2 - t.v0));
    return std::max(0.0f, box.area() - 2.0f * triangleArea);
}

int longestAxis(const Aabb& b) {
    const glm::vec3 e = b.extent();
    return e.x >= e.y ? (e.x >= e.z ? 0 : 2) : (e.y >= e.z ? 1 : 2);
}

// Splits t's box into up to pieces + 1 boxes, always halving the largest one along its
// longest axis, and appends them as references of scene triangle `index`.
void splitTriangle(const Triangle& t, uint32_t index, const Aabb& box, uint32_t pieces, float slack,
                   std::vector<Aabb>& work, RecordVector& out) {
    work.assign(1, box);
    for (uint32_t n = 0; n < pieces; ++n) {
        std::size_t largest = 0;
        for (std::size_t i = 1; i < work.size(); ++i) {
            if (work[i].area() > work[largest].area()) {
                largest = i;
            }
        }
        const Aabb b = work[largest];
        const int axis = longestAxis(b);
        const float position = 0.5f * (b.lower[axis] + b.upper[axis]);
        if (!(position > b.lower[axis] && position < b.upper[axis])) {
            break; // too small to split in float
        }
        Aabb left, right;
        splitBox(t, b, axis, position, slack, left, right);
        if (left.empty() || right.empty()) {
            work[largest] = left.empty() ? right : left;
            continue;
        }
        work[largest] = left;
        work.push_back(right);
    }
    for (const Aabb& b : work) {
        out.push_back({b.lower, index, b.upper, 0.0f});
    }
}

} // namespace

bool presplitRecords(const Scene& scene, float budget, float slack, BuildTeam& team,
                     RecordVector& records) {
    if (records.empty() || !(budget > 0.0f)) {
        return false;
    }
    // Chunks of a fixed size: their partial sums are added in chunk order, and their outputs
    // concatenated in chunk order, whatever thread made them.
    constexpr std::size_t kChunk = 4096;
    const std::size_t chunks = (records.size() + kChunk - 1) / kChunk;
    auto chunkEnd = [&](std::size_t c) { return std::min(records.size(), (c + 1) * kChunk); };
    std::vector<float> priority(records.size());
    std::vector<double> partial(chunks, 0.0);
    team.forEach(chunks, [&](std::size_t c) {
        double sum = 0.0; // stored once: the chunks' sums share cache lines
        for (std::size_t i = c * kChunk; i < chunkEnd(c); ++i) {
            const Aabb box{records[i].lower, records[i].upper};
            priority[i] = std::cbrt(waste(scene.triangles[records[i].sceneIndex], box));
            sum += priority[i];
        }
        partial[c] = sum;
    });
    double total = 0.0;
    for (const double p : partial) {
        total += p;
    }
    if (!(total > 0.0)) {
        return false;
    }
    const double scale = static_cast<double>(budget) * static_cast<double>(records.size()) / total;
    std::vector<RecordVector> outs(chunks);
    team.forEach(chunks, [&](std::size_t c) {
        RecordVector out; // moved into outs[c] once: the chunks' vectors share cache lines
        out.reserve(chunkEnd(c) - c * kChunk + static_cast<std::size_t>(scale * partial[c]) + 64);
        std::vector<Aabb> work;
        for (std::size_t i = c * kChunk; i < chunkEnd(c); ++i) {
            const auto pieces = static_cast<uint32_t>(std::min(64.0, scale * priority[i]));
            if (pieces == 0) {
                out.push_back(records[i]);
                continue;
            }
            splitTriangle(scene.triangles[records[i].sceneIndex], records[i].sceneIndex,
                          Aabb{records[i].lower, records[i].upper}, pieces, slack, work, out);
        }
        outs[c] = std::move(out);
    });
    std::vector<std::size_t> at(chunks + 1, 0);
    for (std::size_t c = 0; c < chunks; ++c) {
        at[c + 1] = at[c] + outs[c].size();
    }
    // A new array: growing the old one would copy references about to be overwritten.
    RecordVector all(at[chunks]);
    team.forEach(chunks, [&](std::size_t c) {
        std::copy(outs[c].begin(), outs[c].end(), all.begin() + static_cast<std::ptrdiff_t>(at[c]));
        RecordVector().swap(outs[c]);
    });
    records.swap(all);
    return true;
}

} // namespace raylab
