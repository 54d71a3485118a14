#include "bench_checks.h"

#include <cstring>

namespace raylab::bench {

namespace {

// Every lane of every block of `answers` against the packets' answer for the same ray, bit for
// bit: returns how many differ, and counts in cameraSeen and shadowSeen the rays compared (set,
// not added to).
std::size_t countMismatches(const BlockedRays& blocked, const BlockAnswers& answers,
                            const std::vector<Hit>& packetHit,
                            const std::vector<uint8_t>& packetAnswer, std::size_t& cameraSeen,
                            std::size_t& shadowSeen) {
    std::size_t mismatches = 0;
    cameraSeen = 0;
    shadowSeen = 0;
    for (std::size_t p = 0; p < blocked.primary.size(); ++p) {
        for (int lane = 0; lane < kPacketSize; ++lane) {
            const std::size_t slot = p * kPacketSize + static_cast<std::size_t>(lane);
            if (const uint32_t i = blocked.primaryRay[slot]; i != kNoRay) {
                const Hit hit = answers.hits[p].hit(lane);
                mismatches += std::memcmp(&hit, &packetHit[i], sizeof(Hit)) != 0 ? 1 : 0;
                ++cameraSeen;
            }
            if (const uint32_t j = blocked.shadowRay[slot]; j != kNoRay) {
                const bool answer = ((answers.occluded[p] >> lane) & 1u) != 0;
                mismatches += answer != (packetAnswer[j] != 0) ? 1 : 0;
                ++shadowSeen;
            }
        }
    }
    return mismatches;
}

} // namespace

bool checkPacketsAndBlocks(const BenchRays& rays, const PacketedRays& packeted,
                           const RaylabAnswers& answers, const BlockedRays* blocked,
                           const BlockAnswers* blockAnswers, const BlockedRays* paired,
                           const BlockAnswers* pairAnswers, BenchReport& report,
                           std::string& error) {
    // The packets' answer for each ray: ray k of a tile is lane k % 8 of the tile's packet
    // k / 8 (bench_rays.h).
    std::vector<Hit> packetHit(rays.primary.size());
    std::vector<uint8_t> packetAnswer(rays.shadow.size());
    for (std::size_t tile = 0; tile < rays.tiles(); ++tile) {
        for (std::size_t i = rays.primaryOffset[tile]; i < rays.primaryOffset[tile + 1]; ++i) {
            const std::size_t k = i - rays.primaryOffset[tile];
            packetHit[i] = answers.packetHits[packeted.primaryOffset[tile] + k / kPacketSize].hit(
                static_cast<int>(k % kPacketSize));
            report.packetMismatches +=
                std::memcmp(&answers.hits[i], &packetHit[i], sizeof(Hit)) != 0 ? 1 : 0;
        }
        for (std::size_t j = rays.shadowOffset[tile]; j < rays.shadowOffset[tile + 1]; ++j) {
            const std::size_t k = j - rays.shadowOffset[tile];
            const unsigned lanes =
                answers.packetOccluded[packeted.shadowOffset[tile] + k / kPacketSize];
            packetAnswer[j] = ((lanes >> (k % kPacketSize)) & 1u) != 0 ? 1 : 0;
            report.packetMismatches += (answers.occluded[j] != 0) != (packetAnswer[j] != 0) ? 1 : 0;
        }
    }
    if (blocked == nullptr) {
        return true;
    }
    std::size_t cameraSeen = 0, shadowSeen = 0;
    if (blockAnswers != nullptr) {
        report.blockMismatches = countMismatches(*blocked, *blockAnswers, packetHit, packetAnswer,
                                                 cameraSeen, shadowSeen);
    }
    if (pairAnswers != nullptr) {
        report.packet16Mismatches =
            countMismatches(*paired, *pairAnswers, packetHit, packetAnswer, cameraSeen, shadowSeen);
    }
    if (cameraSeen != rays.primary.size() || shadowSeen != rays.shadow.size()) {
        error = "the blocks hold " + std::to_string(cameraSeen) + " camera and " +
                std::to_string(shadowSeen) + " shadow rays, not " +
                std::to_string(rays.primary.size()) + " and " + std::to_string(rays.shadow.size());
        return false;
    }
    if (blockAnswers == nullptr) {
        return true;
    }
    report.cameraBlocks = blocked->blocks();
    for (std::size_t b = 0; b < blocked->blocks(); ++b) {
        const uint8_t f = blockAnswers->flags[b];
        report.cameraBlocksThroughCandidates += (f & kCameraCandidates) != 0 ? 1 : 0;
        report.shadowBlocks += blocked->blockShadowRays[b];
        report.shadowBlocksThroughCandidates += (f & kShadowCandidates) != 0 ? 1 : 0;
    }
    return true;
}

} // namespace raylab::bench
