#pragma once
// The bench's checks of raylab's traversals against each other: packets against single rays,
// and 8 x 8 blocks against packets, answer by answer, bit for bit (each must be 0).

#include "bench_blocks.h"
#include "bench_rays.h"
#include "bench_report.h"
#include "core/ray_packet.h"

#include <cstdint>
#include <string>
#include <vector>

namespace raylab::bench {

// What raylab's single rays, packets and blocks answered, per ray or packet of the workload.
struct RaylabAnswers {
    const std::vector<Hit>& hits;                // single rays, per BenchRays::primary
    const std::vector<uint8_t>& occluded;        // single rays, per BenchRays::shadow
    const std::vector<HitPacket>& packetHits;    // per PacketedRays::primary
    const std::vector<unsigned>& packetOccluded; // per PacketedRays::shadow
};

// Counts into report.packetMismatches the packets' answers that differ from the single rays',
// and, when `blocked` is not null, into report.blockMismatches the blocks' answers (when
// blockAnswers is not null) and into report.packet16Mismatches the 16-ray packets' answers for
// the blocks of `paired` (when pairAnswers is not null, traceBlockInPacketPairs) that differ
// from the packets', with the blocks' statistics (report.cameraBlocks, ...). False, with `error`
// set, when the blocks do not hold every ray of the workload.
bool checkPacketsAndBlocks(const BenchRays& rays, const PacketedRays& packeted,
                           const RaylabAnswers& answers, const BlockedRays* blocked,
                           const BlockAnswers* blockAnswers, const BlockedRays* paired,
                           const BlockAnswers* pairAnswers, BenchReport& report,
                           std::string& error);

} // namespace raylab::bench
