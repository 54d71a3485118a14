// Mesh files to a core Scene through Assimp. Assimp does the parsing; this file decides what
// counts as a usable triangle and turns every failure into one line that names the file.

#include "io/mesh_loader.h"

#include "io/gltf_emissive_strength.h"
#include "io/text_util.h"

#include <algorithm>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace raylab {

bool assimpAssertionsThrow(); // assimp_assert.cpp

namespace {

constexpr float kDefaultGrey = 0.75f;

// Whether an OBJ file names a material library (mtllib) that does not exist beside it. Assimp
// only logs this, and then invents materials with its own grey, so we look for ourselves.
bool objMaterialLibraryMissing(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    while (std::getline(in, line)) {
        const std::string text = trim(line);
        if (text.rfind("mtllib", 0) != 0 || text.size() < 7 || !isSpace(text[6])) {
            continue;
        }
        // OBJ allows several library names on one line, separated by spaces.
        std::istringstream names(text.substr(6));
        std::string name;
        while (names >> name) {
            std::error_code ec;
            if (!std::filesystem::exists(path.parent_path() / name, ec)) {
                return true;
            }
        }
    }
    return false;
}

// Checks a PLY header before Assimp sees it. Assimp 5.2 loops forever on a header without an
// "end_header" line, and allocates for every declared element before reading any (gigabytes for a
// forged count); every element takes at least one byte, so a header that declares more elements
// than the file has bytes is truncated or corrupt. Returns an empty string or the reason.
std::string plyHeaderProblem(const std::filesystem::path& path, std::uintmax_t fileSize) {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    std::uintmax_t elements = 0;
    for (int lines = 0; lines < 100000 && std::getline(in, line); ++lines) {
        const std::string text = trim(line);
        if (lines == 0 && text != "ply" && text != "PLY") {
            return "not a PLY file (the first line is not 'ply')";
        }
        if (text == "end_header") {
            return {};
        }
        // Assimp's reading of a malformed element line is not ours to guess ("element 12face 9"),
        // so every run of digits on a line that mentions "element" counts, saturating.
        if (text.find("element") != std::string::npos) {
            std::uintmax_t largest = 0, number = 0;
            for (const char c : text + " ") {
                if (c >= '0' && c <= '9') {
                    number =
                        number > fileSize ? number : number * 10 + static_cast<unsigned>(c - '0');
                } else {
                    largest = std::max(largest, number);
                    number = 0;
                }
            }
            elements += largest;
            if (elements > fileSize) {
                return "the header declares more elements than the file has bytes (truncated or "
                       "corrupt)";
            }
        }
    }
    return "the PLY header has no 'end_header' line";
}

glm::vec3 clampedColour(const aiColor4D& c) {
    auto channel = [](ai_real v) {
        const float f = static_cast<float>(v);
        return std::isfinite(f) ? std::clamp(f, 0.0f, 1.0f) : kDefaultGrey;
    };
    return {channel(c.r), channel(c.g), channel(c.b)};
}

Material toMaterial(const aiMaterial& source, bool forceGrey) {
    Material material;
    aiString name;
    if (source.Get(AI_MATKEY_NAME, name) == aiReturn_SUCCESS) {
        material.name = name.C_Str();
    }
    // Assimp's stand-in material (no material in the file) carries its own 0.6 grey; ours is 0.75.
    if (forceGrey || material.name == AI_DEFAULT_MATERIAL_NAME) {
        return material;
    }
    aiColor4D colour(kDefaultGrey, kDefaultGrey, kDefaultGrey, 1.0f);
    // glTF's base colour first (Assimp also copies it to the diffuse colour), then OBJ's Kd etc.
    if (source.Get(AI_MATKEY_BASE_COLOR, colour) == aiReturn_SUCCESS ||
        source.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == aiReturn_SUCCESS) {
        material.diffuse = clampedColour(colour);
    }
    // Emitted radiance Le: OBJ's Ke or glTF's emissiveFactor (times its
    // KHR_materials_emissive_strength where Assimp reads it; loadMesh applies it where Assimp does
    // not). Not clamped to 1 (lights are brighter than that); a negative or non-finite channel is
    // not light: 0.
    aiColor4D emissive(0.0f, 0.0f, 0.0f, 1.0f);
    if (source.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == aiReturn_SUCCESS) {
        ai_real strength = 1.0f;
        source.Get(AI_MATKEY_EMISSIVE_INTENSITY, strength);
        const auto channel = [strength](ai_real v) {
            const float f = static_cast<float>(v * strength);
            return std::isfinite(f) && f > 0.0f ? f : 0.0f;
        };
        material.emission = {channel(emissive.r), channel(emissive.g), channel(emissive.b)};
    }
    return material;
}

bool isFinite(const aiVector3D& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Assimp's messages can span lines; ours are one line.
std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    std::replace(text.begin(), text.end(), '\r', ' ');
    text = trim(text);
    return text.empty() ? "unknown error" : text;
}

// "1 degenerate triangle", "3 degenerate triangles"; empty when nothing was skipped.
std::string describeCounts(const MeshLoadReport& report) {
    std::string parts;
    auto add = [&](std::size_t n, const char* one, const char* many) {
        if (n != 0) {
            parts += (parts.empty() ? "" : ", ") + std::to_string(n) + " " + (n == 1 ? one : many);
        }
    };
    add(report.nonFiniteTriangles, "non-finite triangle", "non-finite triangles");
    add(report.degenerateTriangles, "degenerate triangle", "degenerate triangles");
    add(report.badIndexFaces, "face with an index out of range",
        "faces with an index out of range");
    add(report.nonTriangleFaces, "point or line", "points or lines");
    return parts;
}

} // namespace

MeshReader::MeshReader() : importer_(std::make_unique<Assimp::Importer>()) {}

MeshReader::~MeshReader() = default;

bool loadMesh(const std::string& path, Scene& scene, MeshLoadReport& report, std::string& error) {
    MeshReader reader;
    return reader.read(path, scene, report, error);
}

bool MeshReader::read(const std::string& path, Scene& scene, MeshLoadReport& report,
                      std::string& error) {
    report = MeshLoadReport{};
    const std::string quoted = "'" + path + "'";

    // Clear messages for the common cases before Assimp gives its own.
    std::error_code ec;
    const std::filesystem::path fsPath(path);
    const auto status = std::filesystem::status(fsPath, ec);
    if (ec || !std::filesystem::exists(status)) {
        error = "cannot open mesh " + quoted + ": " + std::strerror(ENOENT);
        return false;
    }
    if (std::filesystem::is_directory(status)) {
        error = "cannot open mesh " + quoted + ": " + std::strerror(EISDIR);
        return false;
    }
    if (!std::filesystem::is_regular_file(status)) {
        error = "cannot open mesh " + quoted + ": not a regular file";
        return false;
    }
    {
        std::ifstream probe(fsPath, std::ios::binary);
        if (!probe) {
            error = "cannot open mesh " + quoted + ": " + std::strerror(errno);
            return false;
        }
        if (probe.peek() == std::ifstream::traits_type::eof()) {
            error = "cannot load mesh " + quoted + ": the file is empty";
            return false;
        }
    }

    const std::string extension = lowerCase(fsPath.extension().string());
    // Assimp also picks its PLY reader by content, whatever the extension.
    char magic[3] = {};
    std::ifstream(fsPath, std::ios::binary).read(magic, 3);
    const bool looksPly = lowerCase(std::string(magic, 3)) == "ply";
    if (extension == ".ply" || looksPly) {
        const std::uintmax_t size = std::filesystem::file_size(fsPath, ec);
        if (const std::string why = plyHeaderProblem(fsPath, ec ? 0 : size); !why.empty()) {
            error = "cannot load mesh " + quoted + ": " + why;
            return false;
        }
    }
    const bool missingMtl = extension == ".obj" && objMaterialLibraryMissing(fsPath);
    // PLY has no materials; Assimp gives it a white one, which is not what the file says.
    const bool forceGrey = missingMtl || extension == ".ply";

    // Keeps assimp_assert.cpp (Assimp's failed assertions throw instead of aborting) linked in.
    if (!assimpAssertionsThrow()) {
        error = "cannot load mesh " + quoted + ": internal error";
        return false;
    }
    importer_->FreeScene();
    Assimp::Importer& importer = *importer_;
    // Validation first (it rejects indices out of range before any other step reads them), then
    // polygons to triangles and node transforms baked in. Lines and points stay so we can count
    // them. No aiProcess_JoinIdenticalVertices: the scene stores three vertices per triangle
    // anyway, and that step merges a NaN vertex with a finite one, which hides it from the report.
    const unsigned flags =
        aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_PreTransformVertices;
    const aiScene* source = nullptr;
    try {
        source = importer.ReadFile(path, flags);
    } catch (const std::exception& e) {
        error = "cannot load mesh " + quoted + ": " + oneLine(e.what());
        return false;
    }
    if (source == nullptr) {
        error = "cannot load mesh " + quoted + ": " + oneLine(importer.GetErrorString());
        return false;
    }
    if ((source->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0 || source->mNumMeshes == 0) {
        error = "cannot load mesh " + quoted + ": it contains no mesh";
        return false;
    }

    Scene loaded;
    loaded.name = path;
    report.missingMaterialLibrary = missingMtl;
    const std::vector<float> strengths = gltfEmissiveStrengths(path);
    for (unsigned i = 0; i < source->mNumMaterials; ++i) {
        loaded.materials.push_back(toMaterial(*source->mMaterials[i], forceGrey));
        // Assimp's glTF importer reads emissiveFactor but not its strength: applied here.
        if (i < strengths.size()) {
            loaded.materials.back().emission *= strengths[i];
        }
    }
    if (loaded.materials.empty()) {
        loaded.materials.push_back(Material{"default", glm::vec3(kDefaultGrey), glm::vec3(0.0f)});
    }

    for (unsigned m = 0; m < source->mNumMeshes; ++m) {
        const aiMesh& mesh = *source->mMeshes[m];
        const uint32_t material = mesh.mMaterialIndex < loaded.materials.size()
                                      ? mesh.mMaterialIndex
                                      : 0u; // validation rejects this; keep the guard anyway
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) {
                ++report.nonTriangleFaces; // points and lines; Triangulate split the polygons
                continue;
            }
            const unsigned* idx = face.mIndices;
            if (idx[0] >= mesh.mNumVertices || idx[1] >= mesh.mNumVertices ||
                idx[2] >= mesh.mNumVertices) {
                ++report.badIndexFaces;
                continue;
            }
            const aiVector3D& a = mesh.mVertices[idx[0]];
            const aiVector3D& b = mesh.mVertices[idx[1]];
            const aiVector3D& c = mesh.mVertices[idx[2]];
            if (!isFinite(a) || !isFinite(b) || !isFinite(c)) {
                ++report.nonFiniteTriangles;
                continue;
            }
            Triangle t;
            t.v0 = glm::vec3(a.x, a.y, a.z);
            t.v1 = glm::vec3(b.x, b.y, b.z);
            t.v2 = glm::vec3(c.x, c.y, c.z);
            t.material = material;
            if (!isValidTriangle(t)) {
                ++report.degenerateTriangles;
                continue;
            }
            loaded.triangles.push_back(t);
        }
    }

    if (loaded.triangles.empty()) {
        const std::string skipped = describeCounts(report);
        error = "cannot load mesh " + quoted + ": no valid triangle" +
                (skipped.empty() ? std::string() : " (skipped " + skipped + ")");
        return false;
    }
    scene = std::move(loaded);
    return true;
}

std::string describe(const MeshLoadReport& report, const std::string& path) {
    std::string lines;
    if (const std::string counts = describeCounts(report); !counts.empty()) {
        lines += path + ": skipped " + counts + "\n";
    }
    if (report.missingMaterialLibrary) {
        lines += path + ": material library not found, using 0.75 grey\n";
    }
    return lines;
}

} // namespace raylab
