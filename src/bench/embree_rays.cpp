#include "embree_rays.h"

#include "bench_groups.h"
#include "embree_layout.h"

namespace raylab::bench {

namespace {

// One set's rays, array of structures, group by group (PixelGroups), in pixel order.
template <typename R> struct AosSet {
    std::vector<R> rays;
    std::vector<uint32_t> ray;           // rays[k] is the set's ray ray[k]
    std::vector<std::size_t> groupStart; // group g's rays: [groupStart[g], groupStart[g + 1])
};

template <typename R>
AosSet<R> makeAosSet(const PixelGroups& groups, const std::vector<uint32_t>& ofPrimary) {
    AosSet<R> set;
    set.groupStart.push_back(0);
    const std::size_t n = groups.slotsPerGroup();
    for (std::size_t g = 0; g < groups.groups(); ++g) {
        for (std::size_t s = g * n; s < (g + 1) * n; ++s) {
            if (const uint32_t p = groups.slots[s]; p != kNoRay && ofPrimary[p] != kNoRay) {
                set.ray.push_back(ofPrimary[p]);
            }
        }
        set.groupStart.push_back(set.ray.size());
    }
    set.rays.resize(set.ray.size());
    return set;
}

template <typename R> void fill(AosSet<R>& set, const std::vector<Ray>& source) {
    for (std::size_t k = 0; k < set.rays.size(); ++k) {
        setRay(set.rays[k], source[set.ray[k]]);
    }
}

// Single rays (a group is a whole tile) or streams of 8 x 8 pixel tiles.
class AosRays final : public EmbreeRays {
public:
    AosRays(bool stream, const EmbreeScene& scene, const BenchRays& rays)
        : stream_(stream), scene_(scene), rays_(rays),
          groups_(groupPixels(rays, stream ? 8 : rays.tileSize)) {
        const auto ofPrimary = setRaysOfPrimary(rays);
        primary_ = makeAosSet<RTCRayHit>(groups_, ofPrimary[0]);
        shadow_ = makeAosSet<RTCRay>(groups_, ofPrimary[1]);
        bounce_ = makeAosSet<RTCRayHit>(groups_, ofPrimary[2]);
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
        RTCIntersectContext camera = intersectContext(stream_); // single rays: incoherent
        RTCIntersectContext bounce = intersectContext(false);
        const std::size_t g0 = groups_.tileOffset[tile], g1 = groups_.tileOffset[tile + 1];
        if ((sets & kPrimarySet) != 0) {
            closest(primary_, g0, g1, camera);
        }
        if ((sets & kShadowSet) != 0) {
            occluded(g0, g1, camera);
        }
        if ((sets & kBounceSet) != 0) {
            closest(bounce_, g0, g1, bounce);
        }
    }

    EmbreeAnswers answers() const override {
        EmbreeAnswers a;
        a.primary.resize(rays_.primary.size());
        a.occluded.resize(rays_.shadow.size());
        a.bounce.resize(rays_.bounce.size());
        read(primary_, a.primary);
        read(bounce_, a.bounce);
        for (std::size_t k = 0; k < shadow_.rays.size(); ++k) {
            // Embree marks an occluded ray by setting tfar to -inf.
            a.occluded[shadow_.ray[k]] = shadow_.rays[k].tfar < 0.0f ? 1 : 0;
        }
        return a;
    }

private:
    void closest(AosSet<RTCRayHit>& set, std::size_t g0, std::size_t g1,
                 RTCIntersectContext& context) const {
        const RTCScene scene = scene_.handle();
        if (!stream_) {
            for (std::size_t k = set.groupStart[g0]; k < set.groupStart[g1]; ++k) {
                rtcIntersect1(scene, &context, &set.rays[k]);
            }
            return;
        }
        for (std::size_t g = g0; g < g1; ++g) {
            const std::size_t first = set.groupStart[g], m = set.groupStart[g + 1] - first;
            if (m > 0) {
                rtcIntersect1M(scene, &context, &set.rays[first], static_cast<unsigned>(m),
                               sizeof(RTCRayHit));
            }
        }
    }

    void occluded(std::size_t g0, std::size_t g1, RTCIntersectContext& context) {
        const RTCScene scene = scene_.handle();
        if (!stream_) {
            for (std::size_t k = shadow_.groupStart[g0]; k < shadow_.groupStart[g1]; ++k) {
                rtcOccluded1(scene, &context, &shadow_.rays[k]);
            }
            return;
        }
        for (std::size_t g = g0; g < g1; ++g) {
            const std::size_t first = shadow_.groupStart[g], m = shadow_.groupStart[g + 1] - first;
            if (m > 0) {
                rtcOccluded1M(scene, &context, &shadow_.rays[first], static_cast<unsigned>(m),
                              sizeof(RTCRay));
            }
        }
    }

    void read(const AosSet<RTCRayHit>& set, std::vector<Hit>& hits) const {
        for (std::size_t k = 0; k < set.rays.size(); ++k) {
            const RTCRayHit& r = set.rays[k];
            hits[set.ray[k]] =
                hitOf(scene_, r.ray.tfar, r.hit.u, r.hit.v, r.hit.geomID, r.hit.primID);
        }
    }

    bool stream_;
    const EmbreeScene& scene_;
    const BenchRays& rays_;
    PixelGroups groups_;
    AosSet<RTCRayHit> primary_, bounce_;
    AosSet<RTCRay> shadow_;
};

} // namespace

std::unique_ptr<EmbreeRays> makeEmbreeRays(EmbreeCall call, const EmbreeScene& scene,
                                           const BenchRays& rays) {
    if (call == EmbreeCall::Packet16) {
        return makePacketRays(scene, rays);
    }
    return std::make_unique<AosRays>(call == EmbreeCall::Stream, scene, rays);
}

} // namespace raylab::bench
