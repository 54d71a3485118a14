#include "bench_flags.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <string_view>

namespace raylab::bench {

namespace {

// The value of `--name VALUE` or `--name=VALUE` at args[i] (advancing i past a separate value).
// False when args[i] is not that flag; `missing` is set when it is but has no value.
bool flagValue(const std::vector<const char*>& args, std::size_t& i, std::string_view name,
               std::string& value, bool& missing) {
    const std::string_view arg = args[i];
    if (arg == name) {
        missing = i + 1 >= args.size();
        if (!missing) {
            value = args[++i];
        }
        return true;
    }
    if (arg.size() > name.size() && arg.substr(0, name.size()) == name && arg[name.size()] == '=') {
        value = arg.substr(name.size() + 1);
        missing = false;
        return true;
    }
    return false;
}

bool parseBudget(std::string_view text, float& out) {
    float value = 0.0f;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !(value >= 0.0f)) {
        return false;
    }
    out = value;
    return true;
}

} // namespace

bool isEmbreeIsa(const std::string& isa) {
    constexpr std::array<std::string_view, 4> kNames{"sse2", "sse4.2", "avx", "avx2"};
    return std::find(kNames.begin(), kNames.end(), isa) != kNames.end();
}

bool takeBenchFlags(std::vector<const char*>& args, BenchFlags& flags, std::string& error) {
    std::vector<const char*> kept;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view arg = args[i];
        std::string value;
        bool missing = false;
        if (i == 0) {
            kept.push_back(args[i]);
        } else if (arg == "--scalar") {
            flags.scalar = true;
        } else if (arg == "--no-embree") {
            flags.noEmbree = true;
        } else if (arg == "--no-packets") {
            flags.noPackets = true;
        } else if (arg == "--no-blocks") {
            flags.noBlocks = true;
        } else if (arg == "--no-passes") {
            flags.noPasses = true;
        } else if (arg.rfind("--spatial-budget=", 0) == 0 ||
                   arg.rfind("--presplit-budget=", 0) == 0) {
            const bool spatial = arg[2] == 's';
            if (!parseBudget(arg.substr(arg.find('=') + 1),
                             spatial ? flags.spatialBudget : flags.presplitBudget)) {
                error = std::string(arg) + ": not a fraction >= 0";
                return false;
            }
        } else if (flagValue(args, i, "--workload", value, missing)) {
            if (missing || (value != "primary" && value != "bounce")) {
                error = "--workload must be primary or bounce" +
                        (missing ? std::string() : ", not '" + value + "'");
                return false;
            }
            flags.workload = value == "bounce" ? Workload::Bounce : Workload::Primary;
        } else if (flagValue(args, i, "--embree-isa", value, missing)) {
            if (missing || !isEmbreeIsa(value)) {
                error = "--embree-isa must be sse2, sse4.2, avx or avx2" +
                        (missing ? std::string() : ", not '" + value + "'");
                return false;
            }
            flags.embreeIsa = value;
        } else {
            if (arg.rfind("--width", 0) == 0 || arg.rfind("--height", 0) == 0) {
                flags.sizeGiven = true;
            }
            kept.push_back(args[i]);
        }
    }
    args = kept;
    return true;
}

const char* benchFlagsHelp() {
    return "  --workload primary|bounce  primary: a camera ray per pixel and a shadow ray per lit\n"
           "                          hit (default); bounce: also a diffuse bounce ray per hit\n"
           "  --scalar                raylab's scalar reference traversal (binary BVH)\n"
           "  --no-packets            single rays only (no 8-ray packets, no blocks)\n"
           "  --no-blocks             no 8x8 pixel blocks through frustum candidates\n"
           "  --no-passes             no renderer passes (lab and path integrators' samples/s)\n"
           "  --spatial-budget=F      BVH spatial splits: extra references, fraction\n"
           "  --presplit-budget=F     BVH pre-splitting: extra references, fraction\n"
           "  --embree-isa NAME       Embree's instruction set: sse2, sse4.2, avx or avx2\n"
           "                          (default: Embree's own choice, its widest)\n"
           "  --no-embree             skip Embree\n";
}

} // namespace raylab::bench
