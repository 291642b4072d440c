#include "world/import/accessor_reader.hpp"

#include <cstring>

#include <tiny_gltf.h>

#include "world/error.hpp"

namespace onelight::world {
namespace {

size_t componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

int componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        default:
            return 0;
    }
}

/// A checked view of an accessor's bytes: element i starts at data + i * stride.
struct AccessorBytes {
    const unsigned char* data = nullptr;
    size_t count = 0;
    size_t stride = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;
};

const tinygltf::Accessor& checkedAccessor(const tinygltf::Model& model, int accessorIndex,
                                          const std::string& where) {
    if (accessorIndex < 0 || static_cast<size_t>(accessorIndex) >= model.accessors.size()) {
        throw Error(where + ": accessor index " + std::to_string(accessorIndex) +
                    " is out of range (the file has " + std::to_string(model.accessors.size()) +
                    " accessors)");
    }
    return model.accessors[static_cast<size_t>(accessorIndex)];
}

AccessorBytes checkedBytes(const tinygltf::Model& model, int accessorIndex,
                           const std::string& where) {
    const tinygltf::Accessor& accessor = checkedAccessor(model, accessorIndex, where);
    const std::string place = where + " (accessor " + std::to_string(accessorIndex) + ")";
    if (accessor.sparse.isSparse) throw Error(place + ": sparse accessors are not supported");
    AccessorBytes bytes;
    bytes.count = accessor.count;
    bytes.componentType = accessor.componentType;
    bytes.components = componentCount(accessor.type);
    bytes.normalized = accessor.normalized;
    const size_t size = componentSize(accessor.componentType);
    if (size == 0 || bytes.components == 0) {
        throw Error(place + ": unsupported component type " +
                    std::to_string(accessor.componentType) + " or type " +
                    std::to_string(accessor.type));
    }
    if (accessor.count == 0) return bytes;
    if (accessor.bufferView < 0 ||
        static_cast<size_t>(accessor.bufferView) >= model.bufferViews.size()) {
        throw Error(place + ": bufferView " + std::to_string(accessor.bufferView) +
                    " is out of range");
    }
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(accessor.bufferView)];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
        throw Error(place + ": buffer " + std::to_string(view.buffer) + " is out of range");
    }
    const tinygltf::Buffer& buffer = model.buffers[static_cast<size_t>(view.buffer)];
    const uint64_t elementSize = size * static_cast<uint64_t>(bytes.components);
    const uint64_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
    if (stride < elementSize) {
        throw Error(place + ": byteStride " + std::to_string(stride) +
                    " is smaller than the element size " + std::to_string(elementSize));
    }
    const uint64_t viewEnd = static_cast<uint64_t>(view.byteOffset) + view.byteLength;
    if (viewEnd > buffer.data.size()) {
        throw Error(place + ": bufferView ends at byte " + std::to_string(viewEnd) +
                    " but the buffer has " + std::to_string(buffer.data.size()) + " bytes");
    }
    if (accessor.count > view.byteLength) {
        throw Error(place + ": count " + std::to_string(accessor.count) +
                    " does not fit in the bufferView");
    }
    const uint64_t needed =
        static_cast<uint64_t>(accessor.byteOffset) + stride * (accessor.count - 1) + elementSize;
    if (needed > view.byteLength) {
        throw Error(place + ": needs " + std::to_string(needed) + " bytes but the bufferView has " +
                    std::to_string(view.byteLength));
    }
    bytes.data = buffer.data.data() + view.byteOffset + accessor.byteOffset;
    bytes.stride = static_cast<size_t>(stride);
    return bytes;
}

template <typename T>
T load(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof(T));
    return value;
}

float componentAsFloat(const unsigned char* p, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return load<float>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return static_cast<float>(p[0]) / 255.0f;
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const float v = static_cast<float>(static_cast<int8_t>(p[0])) / 127.0f;
            return v < -1.0f ? -1.0f : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return static_cast<float>(load<uint16_t>(p)) / 65535.0f;
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            const float v = static_cast<float>(load<int16_t>(p)) / 32767.0f;
            return v < -1.0f ? -1.0f : v;
        }
        default:
            return 0.0f;
    }
}

}  // namespace

size_t accessorCount(const tinygltf::Model& model, int accessorIndex, const std::string& where) {
    return checkedAccessor(model, accessorIndex, where).count;
}

std::vector<float> readFloatAccessor(const tinygltf::Model& model, int accessorIndex,
                                     int components, const std::string& where) {
    const AccessorBytes bytes = checkedBytes(model, accessorIndex, where);
    const std::string place = where + " (accessor " + std::to_string(accessorIndex) + ")";
    if (bytes.components != components) {
        throw Error(place + ": expected " + std::to_string(components) +
                    " components per element, found " + std::to_string(bytes.components));
    }
    if (bytes.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !bytes.normalized) {
        throw Error(place + ": expected FLOAT or a normalized integer type, found type " +
                    std::to_string(bytes.componentType));
    }
    const size_t size = componentSize(bytes.componentType);
    std::vector<float> values(bytes.count * static_cast<size_t>(components));
    for (size_t i = 0; i < bytes.count; ++i) {
        const unsigned char* element = bytes.data + i * bytes.stride;
        for (int c = 0; c < components; ++c) {
            values[i * static_cast<size_t>(components) + static_cast<size_t>(c)] =
                componentAsFloat(element + static_cast<size_t>(c) * size, bytes.componentType);
        }
    }
    return values;
}

std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int accessorIndex,
                                        const std::string& where) {
    const AccessorBytes bytes = checkedBytes(model, accessorIndex, where);
    const std::string place = where + " (accessor " + std::to_string(accessorIndex) + ")";
    if (bytes.components != 1) throw Error(place + ": indices must be SCALAR");
    std::vector<uint32_t> values(bytes.count);
    for (size_t i = 0; i < bytes.count; ++i) {
        const unsigned char* element = bytes.data + i * bytes.stride;
        switch (bytes.componentType) {
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                values[i] = element[0];
                break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
                values[i] = load<uint16_t>(element);
                break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
                values[i] = load<uint32_t>(element);
                break;
            default:
                throw Error(place +
                            ": indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or "
                            "UNSIGNED_INT, found type " +
                            std::to_string(bytes.componentType));
        }
    }
    return values;
}

}  // namespace onelight::world
