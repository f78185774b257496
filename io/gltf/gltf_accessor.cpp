#include "io/gltf/gltf_accessor.h"

#include <algorithm>
#include <cstring>

namespace penumbra {

namespace {

// An accessor without a bufferView is all zeros (plus sparse values); its count is not
// bounded by any buffer, so it is capped to keep a bad file from exhausting memory.
constexpr size_t kMaxUnbackedComponents = size_t(1) << 28;

const char* type_name(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        case TINYGLTF_TYPE_MAT2:
            return "MAT2";
        case TINYGLTF_TYPE_MAT3:
            return "MAT3";
        case TINYGLTF_TYPE_MAT4:
            return "MAT4";
        default:
            return "unknown type";
    }
}

const char* component_name(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return "byte";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return "unsigned byte";
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return "short";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return "unsigned short";
        case TINYGLTF_COMPONENT_TYPE_INT:
            return "int";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return "unsigned int";
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return "float";
        default:
            return "unknown component type";
    }
}

template <typename T>
T load(const uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));  // glTF data need not be aligned for the host
    return v;
}

// `count` elements of `n` components of type Src, `stride` bytes apart from p, each
// component through `map` into out. The converters below switch on the component type
// once per accessor, not per component: a component switch per element was most of the
// time the loader spends on big meshes, and more so under the fuzzer's instrumentation.
template <typename Src, typename T, typename Map>
void convert_elements(const uint8_t* p, size_t count, size_t n, size_t stride, T* out, Map map) {
    for (size_t i = 0; i < count; ++i, p += stride, out += n)
        for (size_t c = 0; c < n; ++c) out[c] = map(load<Src>(p + c * sizeof(Src)));
}

// As convert_elements, for components stored as they are returned (float, uint32):
// tightly packed ones are one copy.
template <typename T>
void copy_elements(const uint8_t* p, size_t count, size_t n, size_t stride, T* out) {
    if (stride == n * sizeof(T)) {
        std::memcpy(out, p, count * n * sizeof(T));  // glTF data need not be aligned
        return;
    }
    convert_elements<T>(p, count, n, stride, out, [](T v) { return v; });
}

// Floats; normalized conversion per glTF 2.0, section 3.11: signed values clamp at -1.
void convert_floats(const uint8_t* p, size_t count, size_t n, size_t stride, int component_type,
                    bool normalized, float* out) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return convert_elements<int8_t>(p, count, n, stride, out, [normalized](float v) {
                return normalized ? std::max(v / 127.0f, -1.0f) : v;
            });
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return convert_elements<uint8_t>(p, count, n, stride, out, [normalized](float v) {
                return normalized ? v / 255.0f : v;
            });
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return convert_elements<int16_t>(p, count, n, stride, out, [normalized](float v) {
                return normalized ? std::max(v / 32767.0f, -1.0f) : v;
            });
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return convert_elements<uint16_t>(p, count, n, stride, out, [normalized](float v) {
                return normalized ? v / 65535.0f : v;
            });
        case TINYGLTF_COMPONENT_TYPE_INT:
            return convert_elements<int32_t>(p, count, n, stride, out, [normalized](double v) {
                return float(normalized ? std::max(v / 2147483647.0, -1.0) : v);
            });
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return convert_elements<uint32_t>(p, count, n, stride, out, [normalized](double v) {
                return float(normalized ? v / 4294967295.0 : v);
            });
        default:
            return copy_elements(p, count, n, stride, out);
    }
}

// Unsigned integers by value (indices: unsigned byte, short or int).
void convert_uints(const uint8_t* p, size_t count, size_t n, size_t stride, int component_type,
                   bool, uint32_t* out) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return convert_elements<uint8_t>(p, count, n, stride, out,
                                             [](uint32_t v) { return v; });
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return convert_elements<uint16_t>(p, count, n, stride, out,
                                              [](uint32_t v) { return v; });
        default:
            return copy_elements(p, count, n, stride, out);
    }
}

uint32_t to_uint(const uint8_t* p, int component_type) {
    uint32_t v;
    convert_uints(p, 1, 1, 0, component_type, false, &v);
    return v;
}

// The first byte of `count` elements of `elem_size` bytes, `stride` apart, starting
// `offset` bytes into bufferView `view`, after checking that they lie inside the view
// and the view inside its buffer. `user` names the accessor in messages.
const uint8_t* checked_bytes(const GltfContext& ctx, const std::string& user, int view,
                             size_t offset, size_t count, size_t elem_size, size_t stride) {
    const tinygltf::Model& m = ctx.model;
    ctx.check_index(user, "bufferView", view, m.bufferViews.size(), "bufferViews");
    const tinygltf::BufferView& bv = m.bufferViews[size_t(view)];
    ctx.check_index(element("bufferViews", size_t(view)), "buffer", bv.buffer, m.buffers.size(),
                    "buffers");
    const size_t size = m.buffers[size_t(bv.buffer)].data.size();
    if (bv.byteLength > size || bv.byteOffset > size - bv.byteLength)
        ctx.fail(user, "bufferView[" + std::to_string(view) + "] range [" +
                           std::to_string(bv.byteOffset) + ", " +
                           std::to_string(bv.byteOffset + bv.byteLength) + ") exceeds buffer " +
                           std::to_string(bv.buffer) + " of " + std::to_string(size) + " bytes");
    if (count == 0) return nullptr;
    // Last element ends at offset + stride * (count - 1) + elem_size; compared in a
    // form that cannot overflow.
    const size_t len = bv.byteLength;
    if (offset > len || elem_size > len - offset || count - 1 > (len - offset - elem_size) / stride)
        ctx.fail(user, "byteOffset " + std::to_string(offset) + " + " + std::to_string(count) +
                           " elements of " + std::to_string(elem_size) + " bytes, stride " +
                           std::to_string(stride) + ", exceed bufferView[" + std::to_string(view) +
                           "] of " + std::to_string(len) + " bytes");
    return m.buffers[size_t(bv.buffer)].data.data() + bv.byteOffset + offset;
}

// Overwrites out's elements listed in the accessor's sparse section.
template <typename T, typename Convert>
void apply_sparse(const GltfContext& ctx, int index, Convert convert, std::vector<T>& out) {
    const tinygltf::Accessor& a = ctx.model.accessors[size_t(index)];
    const std::string user = element("accessors", size_t(index)) + ".sparse";
    const auto& s = a.sparse;
    if (s.count <= 0 || size_t(s.count) > a.count)
        ctx.fail(user, "count " + std::to_string(s.count) + " not in [1, " +
                           std::to_string(a.count) + "]");
    const int index_type = s.indices.componentType;
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        ctx.fail(user, "indices.componentType " + std::to_string(index_type) +
                           " is not an unsigned integer type");
    const size_t n = size_t(component_count(a.type));
    const size_t csize = size_t(component_size(a.componentType));
    const size_t isize = size_t(component_size(index_type));
    // Sparse indices and values are tightly packed (glTF 2.0, section 3.6.2.3).
    const uint8_t* idx =
        checked_bytes(ctx, user + ".indices", s.indices.bufferView,
                      size_t(std::max(0, s.indices.byteOffset)), size_t(s.count), isize, isize);
    const uint8_t* val = checked_bytes(ctx, user + ".values", s.values.bufferView,
                                       size_t(std::max(0, s.values.byteOffset)), size_t(s.count),
                                       n * csize, n * csize);
    for (size_t k = 0; k < size_t(s.count); ++k) {
        const uint32_t target = to_uint(idx + k * isize, index_type);
        if (target >= a.count)
            ctx.fail(user, "index " + std::to_string(target) + " out of range (" +
                               std::to_string(a.count) + " elements)");
        convert(val + k * n * csize, 1, n, n * csize, a.componentType, a.normalized,
                &out[target * n]);
    }
}

template <typename T, typename Convert>
std::vector<T> read_all(const GltfContext& ctx, int index, Convert convert) {
    const tinygltf::Accessor& a = ctx.model.accessors[size_t(index)];
    const std::string user = element("accessors", size_t(index));
    const size_t n = size_t(component_count(a.type));
    const size_t csize = size_t(component_size(a.componentType));
    if (n == 0) ctx.fail(user, "unknown type " + std::to_string(a.type));
    if (csize == 0) ctx.fail(user, "unknown componentType " + std::to_string(a.componentType));
    // Columns of 1- and 2-byte matrices are padded to 4 bytes (glTF 2.0, section
    // 3.6.2.4); float MAT4 (skins' inverseBindMatrices) has no padding and reads as 16
    // floats per element.
    if ((a.type == TINYGLTF_TYPE_MAT2 || a.type == TINYGLTF_TYPE_MAT3 ||
         a.type == TINYGLTF_TYPE_MAT4) &&
        !(a.type == TINYGLTF_TYPE_MAT4 && a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT))
        ctx.fail(user, "matrix accessors are not supported here");

    std::vector<T> out;
    const size_t elem_size = n * csize;
    if (a.bufferView == -1) {
        if (a.count > kMaxUnbackedComponents / n)
            ctx.fail(user, "count " + std::to_string(a.count) +
                               " is too large for an accessor without a bufferView");
        out.assign(a.count * n, T(0));
    } else {
        const int view = a.bufferView;
        const size_t vstride = view >= 0 && size_t(view) < ctx.model.bufferViews.size()
                                   ? ctx.model.bufferViews[size_t(view)].byteStride
                                   : 0;
        if (vstride != 0 && vstride < elem_size)
            ctx.fail(user, "bufferView[" + std::to_string(view) + "] byteStride " +
                               std::to_string(vstride) + " is smaller than the element size " +
                               std::to_string(elem_size));
        const size_t stride = vstride != 0 ? vstride : elem_size;
        const uint8_t* p = checked_bytes(ctx, user, view, a.byteOffset, a.count, elem_size, stride);
        // count is now bounded by the buffer's size, so this allocation is too.
        out.resize(a.count * n);
        if (a.count > 0) convert(p, a.count, n, stride, a.componentType, a.normalized, out.data());
    }
    if (a.sparse.isSparse) apply_sparse(ctx, index, convert, out);
    return out;
}

}  // namespace

int component_count(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        case TINYGLTF_TYPE_MAT2:
            return 4;
        case TINYGLTF_TYPE_MAT3:
            return 9;
        case TINYGLTF_TYPE_MAT4:
            return 16;
        default:
            return 0;
    }
}

int component_size(int component_type) {
    switch (component_type) {
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
            return 0;  // includes tinygltf's DOUBLE, which glTF 2.0 does not allow
    }
}

std::string describe_accessor(const tinygltf::Accessor& a) {
    return std::string(type_name(a.type)) + " of " + component_name(a.componentType) +
           (a.normalized ? " (normalized)" : "");
}

const tinygltf::Accessor& get_accessor(const GltfContext& ctx, const std::string& user,
                                       const std::string& semantic, int index) {
    ctx.check_index(user, (semantic + " accessor").c_str(), index, ctx.model.accessors.size(),
                    "accessors");
    return ctx.model.accessors[size_t(index)];
}

std::vector<uint8_t> buffer_view_bytes(const GltfContext& ctx, const std::string& user, int view) {
    const uint8_t* p = checked_bytes(ctx, user, view, 0, 1, 0, 1);
    const size_t len = ctx.model.bufferViews[size_t(view)].byteLength;
    return p ? std::vector<uint8_t>(p, p + len) : std::vector<uint8_t>();
}

std::vector<float> read_floats(const GltfContext& ctx, int index) {
    return read_all<float>(ctx, index, convert_floats);
}

std::vector<uint32_t> read_uints(const GltfContext& ctx, int index) {
    const tinygltf::Accessor& a = ctx.model.accessors[size_t(index)];
    if (a.type != TINYGLTF_TYPE_SCALAR ||
        (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        ctx.fail(element("accessors", size_t(index)),
                 "expected SCALAR of unsigned byte, short or int, got " + describe_accessor(a));
    return read_all<uint32_t>(ctx, index, convert_uints);
}

}  // namespace penumbra
