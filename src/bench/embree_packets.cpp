#include "bench_groups.h"
#include "embree_layout.h"

namespace raylab::bench {

namespace {

// Embree's valid mask for a 16-ray packet: -1 for a lane with a ray, 0 for one without.
struct alignas(64) LaneMask {
    int valid[kPacketLanes];
};

// One set's rays in 16-ray packets, one per 4 x 4 pixel tile holding any of the set's rays.
template <typename P> struct PacketSet {
    std::vector<P> packets;
    std::vector<LaneMask> masks;
    std::vector<uint32_t> ray;          // 16 per packet: the set's ray in each lane, or kNoRay
    std::vector<std::size_t> tileStart; // tile i's packets: [tileStart[i], tileStart[i + 1])
};

template <typename P>
PacketSet<P> makePacketSet(const PixelGroups& groups, const std::vector<uint32_t>& ofPrimary) {
    PacketSet<P> set;
    set.tileStart.push_back(0);
    for (std::size_t tile = 0; tile + 1 < groups.tileOffset.size(); ++tile) {
        for (std::size_t g = groups.tileOffset[tile]; g < groups.tileOffset[tile + 1]; ++g) {
            LaneMask mask{};
            std::array<uint32_t, kPacketLanes> lanes{};
            bool any = false;
            for (std::size_t l = 0; l < kPacketLanes; ++l) {
                const uint32_t p = groups.slots[g * kPacketLanes + l];
                lanes[l] = p != kNoRay ? ofPrimary[p] : kNoRay;
                mask.valid[l] = lanes[l] != kNoRay ? -1 : 0;
                any = any || lanes[l] != kNoRay;
            }
            if (any) {
                set.masks.push_back(mask);
                set.ray.insert(set.ray.end(), lanes.begin(), lanes.end());
            }
        }
        set.tileStart.push_back(set.masks.size());
    }
    set.packets.resize(set.masks.size()); // every field zero: a lane without a ray stays so
    return set;
}

template <typename P> void fill(PacketSet<P>& set, const std::vector<Ray>& source) {
    for (std::size_t p = 0; p < set.packets.size(); ++p) {
        for (int l = 0; l < kPacketLanes; ++l) {
            if (const uint32_t r = set.ray[p * kPacketLanes + static_cast<std::size_t>(l)];
                r != kNoRay) {
                setLane(set.packets[p], l, source[r]);
            }
        }
    }
}

class PacketRays final : public EmbreeRays {
public:
    PacketRays(const EmbreeScene& scene, const BenchRays& rays) : scene_(scene), rays_(rays) {
        const PixelGroups groups = groupPixels(rays, 4);
        const auto ofPrimary = setRaysOfPrimary(rays);
        primary_ = makePacketSet<RTCRayHit16>(groups, ofPrimary[0]);
        shadow_ = makePacketSet<RTCRay16>(groups, ofPrimary[1]);
        bounce_ = makePacketSet<RTCRayHit16>(groups, ofPrimary[2]);
        reset(kAllSets);
    }

    void reset(unsigned sets) override {
        if ((sets & kPrimarySet) != 0) {
            fill(primary_, rays_.primary);
        }
        if ((sets & kShadowSet) != 0) {
            fill(shadow_, rays_.shadow);
        }
        if ((sets & kBounceSet) != 0) {
            fill(bounce_, rays_.bounce);
        }
    }

    void traceTile(std::size_t tile, unsigned sets) override {
        const FlushDenormals flush;
        const RTCScene scene = scene_.handle();
        RTCIntersectContext coherent = intersectContext(true);
        RTCIntersectContext incoherent = intersectContext(false);
        if ((sets & kPrimarySet) != 0) {
            for (std::size_t p = primary_.tileStart[tile]; p < primary_.tileStart[tile + 1]; ++p) {
                rtcIntersect16(primary_.masks[p].valid, scene, &coherent, &primary_.packets[p]);
            }
        }
        if ((sets & kShadowSet) != 0) {
            for (std::size_t p = shadow_.tileStart[tile]; p < shadow_.tileStart[tile + 1]; ++p) {
                rtcOccluded16(shadow_.masks[p].valid, scene, &coherent, &shadow_.packets[p]);
            }
        }
        if ((sets & kBounceSet) != 0) {
            for (std::size_t p = bounce_.tileStart[tile]; p < bounce_.tileStart[tile + 1]; ++p) {
                rtcIntersect16(bounce_.masks[p].valid, scene, &incoherent, &bounce_.packets[p]);
            }
        }
    }

    EmbreeAnswers answers() const override {
        EmbreeAnswers a;
        a.primary.resize(rays_.primary.size());
        a.occluded.resize(rays_.shadow.size());
        a.bounce.resize(rays_.bounce.size());
        read(primary_, a.primary);
        read(bounce_, a.bounce);
        for (std::size_t p = 0; p < shadow_.packets.size(); ++p) {
            for (int l = 0; l < kPacketLanes; ++l) {
                if (const uint32_t r = shadow_.ray[p * kPacketLanes + static_cast<std::size_t>(l)];
                    r != kNoRay) {
                    a.occluded[r] = shadow_.packets[p].tfar[l] < 0.0f ? 1 : 0;
                }
            }
        }
        return a;
    }

private:
    void read(const PacketSet<RTCRayHit16>& set, std::vector<Hit>& hits) const {
        for (std::size_t p = 0; p < set.packets.size(); ++p) {
            const RTCRayHit16& r = set.packets[p];
            for (int l = 0; l < kPacketLanes; ++l) {
                if (const uint32_t k = set.ray[p * kPacketLanes + static_cast<std::size_t>(l)];
                    k != kNoRay) {
                    hits[k] = hitOf(scene_, r.ray.tfar[l], r.hit.u[l], r.hit.v[l], r.hit.geomID[l],
                                    r.hit.primID[l]);
                }
            }
        }
    }

    const EmbreeScene& scene_;
    const BenchRays& rays_;
    PacketSet<RTCRayHit16> primary_, bounce_;
    PacketSet<RTCRay16> shadow_;
};

} // namespace

std::unique_ptr<EmbreeRays> makePacketRays(const EmbreeScene& scene, const BenchRays& rays) {
    return std::make_unique<PacketRays>(scene, rays);
}

} // namespace raylab::bench
