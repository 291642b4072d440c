#include "models.hpp"

#include <stdexcept>

#include "shading.hpp"

namespace onelight::lab {

using namespace onelight::glsl;

const std::vector<SpecularModel>& specularModels() {
    static const std::vector<SpecularModel> models = {
        {"bp_none", NDF_BLINN_PHONG, VIS_NONE, reference::Ndf::kBlinnPhong},
        {"bp_kelemen", NDF_BLINN_PHONG, VIS_KELEMEN, reference::Ndf::kBlinnPhong},
        {"bp_schlick", NDF_BLINN_PHONG, VIS_SCHLICK_SMITH, reference::Ndf::kBlinnPhong},
        {"beck_smith", NDF_BECKMANN, VIS_SMITH_CORRELATED, reference::Ndf::kBeckmann},
        {"ggx_smith", NDF_GGX, VIS_SMITH_CORRELATED, reference::Ndf::kGGX},
    };
    return models;
}

const SpecularModel& findModel(std::string_view name) {
    std::string known;
    for (const SpecularModel& m : specularModels()) {
        if (m.name == name) return m;
        known += (known.empty() ? "" : ", ") + std::string(m.name);
    }
    throw std::invalid_argument("unknown model '" + std::string(name) + "' (expected one of " +
                                known + ")");
}

double lobeWidth(const SpecularModel& model, double gloss) {
    return model.ndf == NDF_GGX ? reference::ggxAlpha(gloss) : reference::beckmannM(gloss);
}

}  // namespace onelight::lab
