#include "io/inspection_json.h"

#include <nlohmann/json.hpp>

namespace raylab {

namespace {

using OrderedJson = nlohmann::ordered_json;

OrderedJson vec3Json(const glm::vec3& v) { return OrderedJson::array({v.x, v.y, v.z}); }

} // namespace

std::string inspectionToJson(const PixelInspection& p) {
    OrderedJson j;
    j["pixel"] = {p.x, p.y};
    j["hit"] = p.hit;
    j["cost"] = {{"camera_nodes", p.cameraCost.nodes},
                 {"camera_triangles", p.cameraCost.triangles},
                 {"shadow_nodes", p.shadowCost.nodes},
                 {"shadow_triangles", p.shadowCost.triangles}};
    if (p.hit) {
        j["triangle"] = p.triangle;
        j["material"] = p.material;
        j["t"] = p.t;
        j["point"] = vec3Json(p.point);
        j["rho"] = vec3Json(p.rho);
        j["normal"] = vec3Json(p.normal);
        j["to_light"] = vec3Json(p.toLight);
        j["distance"] = p.distance;
        j["cos_theta"] = p.cosTheta;
        j["D_unshadowed"] = vec3Json(p.directUnshadowed);
        j["D"] = vec3Json(p.direct);
        j["shadow_tested"] = p.shadowTested;
        j["shadowed"] = p.shadowed;
        j["blocker"] = p.blocker
                           ? OrderedJson{{"triangle", p.blocker->triangle}, {"t", p.blocker->t}}
                           : OrderedJson(nullptr);
        j["epsilon"] = p.shadowEpsilon;
        j["t_max"] = p.shadowTMax;
        j["visibility"] = p.visibility;
        j["N"] = vec3Json(p.indirect);
        j["E"] = vec3Json(p.emitted);
        j["R"] = vec3Json(p.radiance);
        j["display"] = {p.display[0], p.display[1], p.display[2]};
        if (!p.path.empty()) {
            OrderedJson path = OrderedJson::array();
            for (const PathVertexRecord& v : p.path) {
                path.push_back({{"point", vec3Json(v.point)},
                                {"rho", vec3Json(v.rho)},
                                {"D", vec3Json(v.direct)},
                                {"adds", vec3Json(v.adds)}});
            }
            j["path"] = std::move(path);
        }
    }
    return j.dump();
}

} // namespace raylab
