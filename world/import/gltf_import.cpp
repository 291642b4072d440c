#include "world/import/gltf_import.hpp"

#include <cmath>
#include <filesystem>
#include <map>

#include <tiny_gltf.h>
#include <glm/gtc/quaternion.hpp>

#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/import/camera_import.hpp"
#include "world/import/extras_import.hpp"
#include "world/import/gltf_json_check.hpp"
#include "world/import/level_limits.hpp"
#include "world/import/light_import.hpp"
#include "world/import/material_import.hpp"
#include "world/import/mesh_import.hpp"

namespace onelight::world {
namespace {

// A prop node's lighting origin, world metres, on its instances from `first`: the one its extras
// give (node space), else the centre of its vertices' world bounds.
void setLightingOrigin(SourceLevel& level, size_t first, const glm::dmat4& world,
                       const NodeExtras& extras) {
    glm::dvec3 origin(0.0);
    if (extras.hasLightingOrigin) {
        origin = glm::dvec3(world * glm::dvec4(glm::dvec3(extras.lightingOrigin), 1.0));
    } else {
        glm::dvec3 lo(1e300), hi(-1e300);
        for (size_t i = first; i < level.instances.size(); ++i)
            for (const Vertex& v : level.instances[i].vertices) {
                const glm::dvec3 p(world * glm::dvec4(glm::dvec3(v.position), 1.0));
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
        if (lo.x <= hi.x) origin = 0.5 * (lo + hi);
    }
    for (size_t i = first; i < level.instances.size(); ++i)
        level.instances[i].lightingOrigin = origin;
}

/// Image loader for tinygltf: pixels are not decoded at compile; embedded images keep their
/// encoded bytes, file references keep only their uri.
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    // Images in a bufferView are copied later, after their range is checked (tinygltf does not).
    if (image->uri.empty() && image->bufferView < 0 && bytes != nullptr && size > 0)
        image->image.assign(bytes, bytes + size);
    return true;
}

std::string firstLine(const std::string& text) {
    const size_t end = text.find('\n');
    return end == std::string::npos ? text : text.substr(0, end);
}

/// Maps the indices of one glTF array to the level's array, in order of first use.
struct UseOrder {
    std::map<int, uint32_t> levelIndex;
    std::vector<int> used;  // glTF index of each level entry
    uint32_t use(int gltfIndex) {
        const auto [it, inserted] =
            levelIndex.emplace(gltfIndex, static_cast<uint32_t>(used.size()));
        if (inserted) used.push_back(gltfIndex);
        return it->second;
    }
};

glm::dmat4 localTransform(const tinygltf::Node& node, const std::string& where) {
    glm::dmat4 m(1.0);
    if (node.matrix.size() == 16) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[static_cast<size_t>(c * 4 + r)];
    } else {
        glm::dvec3 t(0.0), s(1.0);
        glm::dquat q(1.0, 0.0, 0.0, 0.0);
        if (node.translation.size() == 3)
            t = {node.translation[0], node.translation[1], node.translation[2]};
        if (node.scale.size() == 3) s = {node.scale[0], node.scale[1], node.scale[2]};
        if (node.rotation.size() == 4)
            q = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        const double length = glm::length(q);
        q = length > 0.0 ? q / length : glm::dquat(1.0, 0.0, 0.0, 0.0);
        m = glm::dmat4(glm::mat3_cast(q));
        m[0] *= s.x;
        m[1] *= s.y;
        m[2] *= s.z;
        m[3] = glm::dvec4(t, 1.0);
    }
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r]))
                throw Error(where + ": transform is NaN or Inf; expected finite numbers");
    return m;
}

struct Importer {
    const tinygltf::Model& model;
    const std::string& file;
    std::string folder;
    SourceLevel level{};
    UseOrder materials{}, textures{}, images{};
    uint32_t defaultMaterial = kNoIndex;
    std::string skyImage{};  // extras.onelight.sky's image, relative to the glTF's folder

    uint32_t useTexture(int gltfTexture) {
        if (gltfTexture < 0) return kNoIndex;
        if (static_cast<size_t>(gltfTexture) >= model.textures.size())
            throw Error(file + ": texture index " + std::to_string(gltfTexture) +
                        " is out of range");
        return textures.use(gltfTexture);
    }

    uint32_t useMaterial(int gltfMaterial) {
        if (gltfMaterial < 0) {
            if (defaultMaterial == kNoIndex) defaultMaterial = materials.use(-1);
            return defaultMaterial;
        }
        if (static_cast<size_t>(gltfMaterial) >= model.materials.size())
            throw Error(file + ": material index " + std::to_string(gltfMaterial) +
                        " is out of range");
        return materials.use(gltfMaterial);
    }

    void visit(int nodeIndex, const glm::dmat4& parent, uint32_t entity, std::vector<bool>& seen,
               int depth) {
        if (nodeIndex < 0 || static_cast<size_t>(nodeIndex) >= model.nodes.size())
            throw Error(file + ": node index " + std::to_string(nodeIndex) + " is out of range");
        if (seen[static_cast<size_t>(nodeIndex)])
            throw Error(file + ": node " + std::to_string(nodeIndex) +
                        " appears twice in the hierarchy; expected a tree");
        if (depth > 1024) throw Error(file + ": node hierarchy deeper than 1024");
        seen[static_cast<size_t>(nodeIndex)] = true;
        const tinygltf::Node& node = model.nodes[static_cast<size_t>(nodeIndex)];
        const std::string name =
            node.name.empty() ? "node_" + std::to_string(nodeIndex) : node.name;
        const std::string where = file + ": node '" + name + "'";
        const glm::dmat4 world = parent * localTransform(node, where);
        const NodeExtras extras = parseNodeExtras(node.extras, where);

        if (extras.hasGrid && !level.hasGridBounds) {
            level.hasGridBounds = true;
            level.gridMin = extras.gridMin;
            level.gridMax = extras.gridMax;
        }
        if (extras.texelsPerMetre > 0.0f) level.texelsPerMetre = extras.texelsPerMetre;
        if (extras.probeSpacing > 0.0f) level.probeSpacing = extras.probeSpacing;
        if (extras.diffuseModel) level.diffuseModel = *extras.diffuseModel;
        if (extras.glossMips) level.glossMips = *extras.glossMips;
        if (extras.hasSky) {
            level.skyRadiance = extras.skyRadiance;
            skyImage = extras.skyImage;
        }
        if (extras.hasExposure && node.camera < 0 && !level.hasExposure) {
            level.hasExposure = true;
            level.exposureEv100 = extras.exposureEv100;
        }
        if (extras.dynamic || extras.spawn || extras.probe) {
            Entity e;
            e.name = name;
            e.flags = (extras.dynamic ? kEntityDynamic : 0u) | (extras.mover ? kEntityMover : 0u) |
                      (extras.spawn ? kEntitySpawn : 0u) | (extras.probe ? kEntityProbe : 0u);
            e.position = glm::vec3(glm::dvec3(world[3]));
            e.rotation = rotationOf(world);
            e.scale =
                glm::vec3(glm::length(glm::dvec3(world[0])), glm::length(glm::dvec3(world[1])),
                          glm::length(glm::dvec3(world[2])));
            if (extras.hasProbeBox) {
                e.probeBoxMin = extras.probeBoxMin;
                e.probeBoxMax = extras.probeBoxMax;
            }
            level.entities.push_back(e);
            if (extras.dynamic) entity = static_cast<uint32_t>(level.entities.size() - 1);
            if (extras.mover) {
                Mover shuttle;
                shuttle.entity = static_cast<uint32_t>(level.entities.size() - 1);
                shuttle.kind = MoverKind::kShuttle;
                shuttle.pos1 = shuttle.pos2 = e.position;
                shuttle.pos2 += extras.moverOffset;
                shuttle.period = extras.moverPeriod;
                level.movers.movers.push_back(shuttle);
            }
        }

        const auto lightExtension = node.extensions.find("KHR_lights_punctual");
        if (lightExtension != node.extensions.end() && lightExtension->second.Has("light")) {
            const tinygltf::Value& indexValue = lightExtension->second.Get("light");
            const int lightIndex = indexValue.IsInt() ? indexValue.Get<int>() : -1;
            if (lightIndex < 0 || static_cast<size_t>(lightIndex) >= model.lights.size())
                throw Error(where + ": KHR_lights_punctual light index " +
                            std::to_string(lightIndex) + " is out of range");
            level.lights.push_back(importLight(model.lights[static_cast<size_t>(lightIndex)], world,
                                               name, extras.role, where));
        } else if (extras.hasRole) {
            throw Error(where + ": extras.onelight.role is set but the node has no light");
        }

        if (node.camera >= 0) {
            if (static_cast<size_t>(node.camera) >= model.cameras.size())
                throw Error(where + ": camera index " + std::to_string(node.camera) +
                            " is out of range");
            Camera camera =
                importCamera(model.cameras[static_cast<size_t>(node.camera)], world, name, where);
            camera.hasExposure = extras.hasExposure;
            camera.exposureEv100 = extras.exposureEv100;
            level.cameras.push_back(camera);
        }

        if (node.mesh >= 0) {
            if (static_cast<size_t>(node.mesh) >= model.meshes.size())
                throw Error(where + ": mesh index " + std::to_string(node.mesh) +
                            " is out of range");
            const tinygltf::Mesh& mesh = model.meshes[static_cast<size_t>(node.mesh)];
            const size_t firstOfNode = level.instances.size();
            for (size_t p = 0; p < mesh.primitives.size(); ++p) {
                ImportedPrimitive imported =
                    importPrimitive(model, node.mesh, static_cast<int>(p), file);
                if (!imported.isTriangles || imported.indices.empty()) continue;
                MeshInstance instance;
                instance.nodeName = name;
                instance.meshName =
                    mesh.name.empty() ? "mesh_" + std::to_string(node.mesh) : mesh.name;
                instance.primitive = static_cast<uint32_t>(p);
                instance.material = useMaterial(mesh.primitives[p].material);
                instance.worldFromLocal = world;
                instance.vertices = std::move(imported.vertices);
                instance.indices = std::move(imported.indices);
                instance.hasUv1 = imported.hasUv1;
                instance.dynamic = entity != kNoIndex;
                instance.entity = entity;
                instance.prop = extras.prop && !instance.dynamic;
                level.instances.push_back(std::move(instance));
            }
            if (extras.prop) setLightingOrigin(level, firstOfNode, world, extras);
        }
        for (int child : node.children) visit(child, world, entity, seen, depth + 1);
    }

    std::vector<unsigned char> bufferViewBytes(int viewIndex, int imageIndex) const {
        const std::string where = file + ": image " + std::to_string(imageIndex);
        if (static_cast<size_t>(viewIndex) >= model.bufferViews.size())
            throw Error(where + ": bufferView " + std::to_string(viewIndex) + " is out of range");
        const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(viewIndex)];
        if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
            throw Error(where + ": buffer " + std::to_string(view.buffer) + " is out of range");
        const std::vector<unsigned char>& data =
            model.buffers[static_cast<size_t>(view.buffer)].data;
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
            throw Error(where + ": bufferView bytes lie outside buffer " +
                        std::to_string(view.buffer));
        return std::vector<unsigned char>(
            data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset),
            data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset + view.byteLength));
    }

    void resolveMaterialsAndTextures() {
        std::vector<Material> converted;
        for (size_t i = 0; i < materials.used.size(); ++i) {
            const int source = materials.used[i];
            if (source < 0) {
                converted.push_back(world::defaultMaterial());
                continue;
            }
            Material m = convertMaterial(model.materials[static_cast<size_t>(source)],
                                         [this](int t) { return useTexture(t); });
            if (m.name.empty()) m.name = "material_" + std::to_string(source);
            converted.push_back(m);
        }
        level.materials = std::move(converted);
        for (int sourceIndex : textures.used) {
            const tinygltf::Texture& source = model.textures[static_cast<size_t>(sourceIndex)];
            Texture texture;
            if (source.source >= 0) {
                if (static_cast<size_t>(source.source) >= model.images.size())
                    throw Error(file + ": texture " + std::to_string(sourceIndex) + " image " +
                                std::to_string(source.source) + " is out of range");
                texture.image = images.use(source.source);
            }
            if (source.sampler >= 0) {
                if (static_cast<size_t>(source.sampler) >= model.samplers.size())
                    throw Error(file + ": texture " + std::to_string(sourceIndex) + " sampler " +
                                std::to_string(source.sampler) + " is out of range");
                const tinygltf::Sampler& s = model.samplers[static_cast<size_t>(source.sampler)];
                texture.sampler.magFilter =
                    static_cast<uint16_t>(s.magFilter < 0 ? 0 : s.magFilter);
                texture.sampler.minFilter =
                    static_cast<uint16_t>(s.minFilter < 0 ? 0 : s.minFilter);
                texture.sampler.wrapS = static_cast<uint16_t>(s.wrapS);
                texture.sampler.wrapT = static_cast<uint16_t>(s.wrapT);
            }
            level.textures.push_back(texture);
        }
        for (int sourceIndex : images.used) {
            const tinygltf::Image& source = model.images[static_cast<size_t>(sourceIndex)];
            Image image;
            image.name = source.name;
            image.mimeType = source.mimeType;
            if (!source.uri.empty()) {
                image.uri =
                    (std::filesystem::path(folder) / source.uri).lexically_normal().string();
            } else if (source.bufferView >= 0) {
                image.encodedBytes = bufferViewBytes(source.bufferView, sourceIndex);
            } else {
                image.encodedBytes = source.image;
            }
            level.images.push_back(std::move(image));
        }
    }
};

// tinygltf's file access, limited to regular files (a FIFO or /dev/zero would block or never
// end), with no shell-style expansion of paths, and never writing. `user` collects what was read.
bool anyFileExists(const std::string& path, void*) {
    std::error_code ec;  // whatever it is: the read then says why it is not a file to read
    return std::filesystem::exists(path, ec);
}

std::string unexpandedPath(const std::string& path, void*) {
    return path;
}

bool readRegularFileFor(std::vector<unsigned char>* out, std::string* error,
                        const std::string& path, void* user) {
    try {
        *out = readRegularFile(path, "a buffer or image the glTF names");
        static_cast<std::vector<std::string>*>(user)->push_back(path);
        return true;
    } catch (const Error& e) {
        if (error) *error += std::string(e.what()) + "\n";
        return false;
    }
}

bool refuseToWrite(std::string* error, const std::string&, const std::vector<unsigned char>&,
                   void*) {
    if (error) *error += "the importer writes no files\n";
    return false;
}

}  // namespace

SourceLevel importGltf(const std::string& path) {
    return importGltfBytes(readRegularFile(path, "a .gltf or .glb file"), path);
}

SourceLevel importGltfBytes(std::vector<uint8_t> bytes, const std::string& path) {
    // Our own checks first (glb version, JSON depth, every field's type); tinygltf then parses
    // what passed, and reads buffers and images only as regular files.
    const GltfFile file = checkGltfBytes(std::move(bytes), path);
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&keepEncodedImage, nullptr);
    std::vector<std::string> filesRead;
    loader.SetFsCallbacks(tinygltf::FsCallbacks{&anyFileExists, &unexpandedPath,
                                                &readRegularFileFor, &refuseToWrite, &filesRead});
    std::string error, warning;
    const std::string folder = std::filesystem::path(path).parent_path().string();
    const bool loaded =
        file.binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, file.bytes.data(),
                                                  unsigned(file.bytes.size()), folder)
                    : loader.LoadASCIIFromString(&model, &error, &warning,
                                                 reinterpret_cast<const char*>(file.bytes.data()),
                                                 unsigned(file.bytes.size()), folder);
    if (!loaded)
        throw Error(path + ": not a valid glTF 2.0 file: " +
                    (error.empty() ? std::string("unknown error") : firstLine(error)));

    Importer importer{model, path, folder};
    importer.level.sourcePath = path;
    importer.level.inputFiles.push_back(path);
    for (const std::string& read : filesRead) importer.level.inputFiles.push_back(read);
    std::vector<int> roots;
    if (!model.scenes.empty()) {
        const int sceneIndex =
            model.defaultScene >= 0 && static_cast<size_t>(model.defaultScene) < model.scenes.size()
                ? model.defaultScene
                : 0;
        roots = model.scenes[static_cast<size_t>(sceneIndex)].nodes;
    } else {
        std::vector<bool> isChild(model.nodes.size(), false);
        for (const tinygltf::Node& node : model.nodes)
            for (int child : node.children)
                if (child >= 0 && static_cast<size_t>(child) < model.nodes.size())
                    isChild[static_cast<size_t>(child)] = true;
        for (size_t i = 0; i < model.nodes.size(); ++i)
            if (!isChild[i]) roots.push_back(static_cast<int>(i));
    }
    std::vector<bool> seen(model.nodes.size(), false);
    for (int root : roots) importer.visit(root, glm::dmat4(1.0), kNoIndex, seen, 0);
    importer.resolveMaterialsAndTextures();
    if (!importer.skyImage.empty()) {
        // The sky's image joins the level's images (a file reference; decoded by the baker and
        // the runtime, which both check it is a readable .hdr).
        world::Image sky;
        sky.name = "sky";
        sky.mimeType = "image/vnd.radiance";
        sky.uri = (std::filesystem::path(importer.folder) / importer.skyImage)
                      .lexically_normal()
                      .string();
        importer.level.skyImage = uint32_t(importer.level.images.size());
        importer.level.images.push_back(std::move(sky));
    }
    checkLevelLimits(importer.level);
    return std::move(importer.level);
}

}  // namespace onelight::world
