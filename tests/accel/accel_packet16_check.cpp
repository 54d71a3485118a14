#include "accel_packet16_check.h"

#include "accel_check.h"
#include "core/bvh/bvh_packet.h"
#include "core/triangle_intersection.h"

#include <algorithm>
#include <gtest/gtest.h>

namespace raylab::accel_test {

std::string packet16PathName(const ::testing::TestParamInfo<Packet16Path>& path) {
    return path.param == Packet16Path::Avx512 ? "Avx512" : "TwoPackets8";
}

std::vector<Packet16Path> packet16Paths() {
    if (bvhPacket16Supported()) {
        return {Packet16Path::Avx512, Packet16Path::TwoPackets8};
    }
    return {Packet16Path::TwoPackets8};
}

bool rememberedTriangleHit(const Bvh& bvh, const LastOccluder& last, const Ray* rays,
                           unsigned lanes) {
    if (last.block >= bvh.triangleBlocks.size() || last.slot < 0 || last.slot >= kWideLanes) {
        return false;
    }
    const BvhTriangleBlock& block = bvh.triangleBlocks[last.block];
    glm::vec3 v[3];
    for (int k = 0; k < 3; ++k) {
        for (int a = 0; a < 3; ++a) {
            v[k][a] = block.vertex[k][a][last.slot];
        }
    }
    for (unsigned m = lanes; m != 0; m &= m - 1) {
        const Ray& ray = rays[__builtin_ctz(m)];
        float t, u, w;
        if (intersectTriangle(WatertightRay(ray), v[0], v[1], v[2], t, u, w) && t >= ray.tMin &&
            t <= ray.tMax) {
            return true;
        }
    }
    return false;
}

int expectPacket16(const Bvh& bvh, const Ray* rays, int count, unsigned mask, Packet16Path path,
                   const Scene* scene, int& failures, LastOccluder* last) {
    RayPacket packets[2];
    for (int i = 0; i < count; ++i) {
        packets[i / kPacketSize].set(i % kPacketSize, rays[i]);
    }
    packets[0].lanes &= mask & 0xffu;
    packets[1].lanes &= mask >> kPacketSize;
    HitPacket hits[2];
    hits[0].set(0, Hit{1.0f, 0.5f, 0.5f, 3}); // stale contents must be overwritten
    closestHit16(bvh, packets[0], packets[1], hits[0], hits[1], path);
    const unsigned occluded = anyHit16(bvh, packets[0], packets[1], path);
    if (last != nullptr) {
        const LastOccluder before = *last;
        const unsigned withLast = anyHit16(bvh, packets[0], packets[1], path, last);
        if (withLast != occluded) {
            ++failures;
            ADD_FAILURE() << "occluded lanes " << occluded << " without a last occluder, "
                          << withLast << " with block " << before.block << " slot " << before.slot;
        }
        // A triangle newly remembered (by the traversal or from the remembered one's block) is one
        // that an occluded lane's ray hits.
        if ((last->block != before.block || last->slot != before.slot) &&
            !rememberedTriangleHit(bvh, *last, rays, withLast)) {
            ++failures;
            ADD_FAILURE() << "block " << last->block << " slot " << last->slot
                          << " remembered, which no occluded lane of " << withLast << " hits";
        }
    }
    int hitCount = 0;
    for (int i = 0; i < kPacket16Size; ++i) {
        const Hit hit = hits[i / kPacketSize].hit(i % kPacketSize);
        const bool any = ((occluded >> i) & 1u) != 0;
        if (i >= count || ((mask >> i) & 1u) == 0) {
            if (hit.found() || any) {
                ++failures;
                ADD_FAILURE() << "lane " << i << " without a ray answered";
            }
            continue;
        }
        const Ray& ray = rays[i];
        const Hit single = closestHit(bvh, ray);
        bool ok = sameHit(hit, single) && sameHit(hit, closestHitScalar(bvh, ray)) &&
                  any == anyHit(bvh, ray) && any == anyHitScalar(bvh, ray);
        if (scene != nullptr) {
            ok = ok && sameHit(hit, closestHitBruteForce(*scene, ray)) &&
                 any == anyHitBruteForce(*scene, ray);
        }
        if (!ok && failures++ < 5) {
            ADD_FAILURE() << "lane " << i << ": packet t=" << hit.t << " tri=" << hit.triangle
                          << " any=" << any << ", single t=" << single.t
                          << " tri=" << single.triangle << " any=" << anyHit(bvh, ray);
        }
        hitCount += single.found() ? 1 : 0;
    }
    return hitCount;
}

int expectPackets16(const Bvh& bvh, const std::vector<Ray>& rays, Packet16Path path,
                    const Scene* scene, int size) {
    int hits = 0, failures = 0;
    LastOccluder last;
    for (std::size_t first = 0; first < rays.size() && failures < 5; first += size) {
        const int count = static_cast<int>(
            std::min<std::size_t>(static_cast<std::size_t>(size), rays.size() - first));
        hits += expectPacket16(bvh, &rays[first], count, 0xffffu, path, scene, failures, &last);
    }
    return hits;
}

int expectPacket64(const Bvh& bvh, const Ray* rays, int count, uint64_t mask, Packet16Path path,
                   const Scene* scene, int& failures) {
    constexpr int kPackets = 8;
    RayPacket packets[kPackets];
    for (int i = 0; i < count; ++i) {
        packets[i / kPacketSize].set(i % kPacketSize, rays[i]);
    }
    for (int k = 0; k < kPackets; ++k) {
        packets[k].lanes &= static_cast<unsigned>(mask >> (kPacketSize * k)) & 0xffu;
    }
    HitPacket hits[kPackets];
    for (HitPacket& h : hits) {
        h.set(0, Hit{1.0f, 0.5f, 0.5f, 3}); // stale contents must be overwritten
    }
    closestHit64(bvh, packets, hits, path);
    int hitCount = 0;
    for (int i = 0; i < kPackets * kPacketSize; ++i) {
        const Hit hit = hits[i / kPacketSize].hit(i % kPacketSize);
        if (i >= count || ((mask >> i) & 1u) == 0) {
            if (hit.found()) {
                ++failures;
                ADD_FAILURE() << "lane " << i << " without a ray answered";
            }
            continue;
        }
        const Ray& ray = rays[i];
        const Hit single = closestHit(bvh, ray);
        bool ok = sameHit(hit, single) && sameHit(hit, closestHitScalar(bvh, ray));
        if (scene != nullptr) {
            ok = ok && sameHit(hit, closestHitBruteForce(*scene, ray));
        }
        if (!ok && failures++ < 5) {
            ADD_FAILURE() << "lane " << i << ": packet t=" << hit.t << " tri=" << hit.triangle
                          << ", single t=" << single.t << " tri=" << single.triangle;
        }
        hitCount += single.found() ? 1 : 0;
    }
    return hitCount;
}

int expectPackets64(const Bvh& bvh, const std::vector<Ray>& rays, Packet16Path path,
                    const Scene* scene) {
    constexpr std::size_t kSize = 64;
    int hits = 0, failures = 0;
    for (std::size_t first = 0; first < rays.size() && failures < 5; first += kSize) {
        const int count = static_cast<int>(std::min(kSize, rays.size() - first));
        hits += expectPacket64(bvh, &rays[first], count, ~uint64_t{0}, path, scene, failures);
    }
    EXPECT_EQ(failures, 0);
    return hits;
}

} // namespace raylab::accel_test
