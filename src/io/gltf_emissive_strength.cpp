#include "io/gltf_emissive_strength.h"

#include "io/text_util.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

namespace raylab {

namespace {

bool endsWith(const std::string& text, const char* suffix) {
    const std::size_t n = std::strlen(suffix);
    return text.size() >= n && text.compare(text.size() - n, n, suffix) == 0;
}

uint32_t littleEndian32(const unsigned char* p) {
    return static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 |
           static_cast<uint32_t>(p[2]) << 16 | static_cast<uint32_t>(p[3]) << 24;
}

// The JSON text of a .glb: its first chunk, which must be of type JSON.
bool glbJson(std::ifstream& in, std::string& json) {
    unsigned char header[20];
    if (!in.read(reinterpret_cast<char*>(header), sizeof header)) {
        return false;
    }
    const uint32_t magic = littleEndian32(header);
    const uint32_t chunkLength = littleEndian32(header + 12);
    const uint32_t chunkType = littleEndian32(header + 16);
    if (magic != 0x46546C67u || chunkType != 0x4E4F534Au || chunkLength > kMaxGltfJsonBytes) {
        return false;
    }
    json.resize(chunkLength);
    return static_cast<bool>(in.read(json.data(), chunkLength));
}

} // namespace

std::vector<float> gltfEmissiveStrengths(const std::string& path) {
    const std::string lower = lowerCase(path);
    const bool glb = endsWith(lower, ".glb");
    if (!glb && !endsWith(lower, ".gltf")) {
        return {};
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return {};
    }
    std::string json;
    if (glb) {
        if (!glbJson(in, json)) {
            return {};
        }
    } else {
        json.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        if (json.size() > kMaxGltfJsonBytes) {
            return {};
        }
    }
    const nlohmann::json root = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
    if (!root.is_object() || !root.contains("materials") || !root["materials"].is_array()) {
        return {};
    }
    std::vector<float> strengths;
    for (const nlohmann::json& material : root["materials"]) {
        float strength = 1.0f;
        if (material.is_object() && material.contains("extensions") &&
            material["extensions"].is_object() &&
            material["extensions"].contains("KHR_materials_emissive_strength")) {
            const nlohmann::json& extension =
                material["extensions"]["KHR_materials_emissive_strength"];
            if (extension.is_object() && extension.contains("emissiveStrength") &&
                extension["emissiveStrength"].is_number()) {
                const double value = extension["emissiveStrength"].get<double>();
                strength = std::isfinite(value) && value >= 0.0 ? static_cast<float>(value) : 0.0f;
            }
        }
        strengths.push_back(strength);
    }
    return strengths;
}

} // namespace raylab
