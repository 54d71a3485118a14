#pragma once
// glTF's KHR_materials_emissive_strength, which Debian's Assimp 5.2.5 does not read: each
// material's emissiveStrength (1 where it has none), read from the .gltf's JSON or a .glb's JSON
// chunk, in the file's material order (the order in which Assimp's glTF importer makes its
// materials).

#include <string>
#include <vector>

namespace raylab {

// The strengths of the file's materials; empty for a file that is not glTF or whose JSON cannot be
// read (the caller then multiplies by nothing). Never throws; reads at most the file's first
// kMaxGltfJsonBytes of JSON.
inline constexpr std::size_t kMaxGltfJsonBytes = 256u << 20;
std::vector<float> gltfEmissiveStrengths(const std::string& path);

} // namespace raylab
