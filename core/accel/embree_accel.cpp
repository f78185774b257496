#include "core/accel/embree_accel.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mutex>
#include <string>

#include "core/accel/embree_hit_map.h"
#include "core/accel/flattened_instances.h"
#include "core/error.h"
#include "core/log.h"
#include "core/scene/motion.h"

namespace penumbra {

namespace {

// Embree reports errors through a callback from inside C code, where throwing is not
// allowed: log them, remember the first, and throw once control is back in ours.
struct ErrorSink {
    std::mutex mutex;
    std::string first;
};

void error_callback(void* user, RTCError code, const char* str) {
    auto* sink = static_cast<ErrorSink*>(user);
    LOG_ERROR("embree: error " << static_cast<int>(code) << ": " << (str ? str : ""));
    std::lock_guard<std::mutex> lock(sink->mutex);
    if (sink->first.empty()) sink->first = str ? str : "unknown error";
}

// A device with Embree's config string `config`, else PENUMBRA_EMBREE_CONFIG's (e.g.
// "isa=sse4.2", "isa=avx2", "verbose=1"), so that every code path Embree has can run on
// one machine. Images do not depend on it: EmbreeAccel recomputes every hit it reports.
RTCDevice new_device(const std::string& config = {}) {
    std::string c = config;
    if (c.empty())
        if (const char* env = std::getenv("PENUMBRA_EMBREE_CONFIG")) c = env;
    RTCDevice device = rtcNewDevice(c.empty() ? nullptr : c.c_str());
    if (!device)
        throw InternalError("embree: cannot create a device" +
                            (c.empty() ? std::string() : " with config \"" + c + "\""));
    return device;
}

bool memory_callback(void* user, ssize_t bytes, bool) {
    static_cast<std::atomic<int64_t>*>(user)->fetch_add(bytes, std::memory_order_relaxed);
    return true;
}

// Transform motion as quaternion decompositions (motion.h), so that Embree slerps the
// rotation instead of blending matrices (which would shrink a rotating object).
void set_transform_steps(RTCGeometry g, const std::vector<Transform>& steps) {
    const std::vector<QuatDecomposition> ds = decompose_steps(steps);
    rtcSetGeometryTimeStepCount(g, static_cast<unsigned>(ds.size()));
    for (size_t k = 0; k < ds.size(); ++k) {
        const QuatDecomposition& d = ds[k];
        RTCQuaternionDecomposition qd;
        rtcInitQuaternionDecomposition(&qd);
        rtcQuaternionDecompositionSetScale(&qd, d.scale.x, d.scale.y, d.scale.z);
        rtcQuaternionDecompositionSetSkew(&qd, d.skew.x, d.skew.y, d.skew.z);
        rtcQuaternionDecompositionSetShift(&qd, d.shift.x, d.shift.y, d.shift.z);
        rtcQuaternionDecompositionSetQuaternion(&qd, d.r, d.i, d.j, d.k);
        rtcQuaternionDecompositionSetTranslation(&qd, d.translation.x, d.translation.y,
                                                 d.translation.z);
        rtcSetGeometryTransformQuaternion(g, static_cast<unsigned>(k), &qd);
    }
}

}  // namespace

Mat4 embree_transform_at(const std::vector<Transform>& steps, float u) {
    RTCDevice device = new_device();
    RTCScene empty = rtcNewScene(device);
    rtcCommitScene(empty);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, empty);
    set_transform_steps(g, steps);
    rtcCommitGeometry(g);
    float xfm[12];
    rtcGetGeometryTransform(g, u, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
    rtcReleaseGeometry(g);
    rtcReleaseScene(empty);
    rtcReleaseDevice(device);
    Mat4 m = Mat4::identity();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 3; ++r) m(r, c) = xfm[c * 3 + r];
    return m;
}

struct EmbreeAccel::Impl {
    ErrorSink errors;
    std::atomic<int64_t> memory{0};  // bytes Embree has allocated, from its monitor
    RTCDevice device = nullptr;
    RTCScene top = nullptr;
    std::vector<RTCScene> object_scenes;  // per object; null where every placement is flat
    EmbreeHitMap hits;
    // Queries whose tmin is above this are filtered (needs_filter): -inf where some
    // instance moves or some instanced mesh deforms (every query), else 0.
    float filter_above = 0;
    // Vertex bytes copied out of the Scene (EmbreeAccel::copied_bytes).
    size_t copied_bytes = 0;

    void throw_if_error(const char* what) {
        std::lock_guard<std::mutex> lock(errors.mutex);
        if (!errors.first.empty())
            throw InternalError(std::string("embree: ") + what + ": " + errors.first);
    }

    // The build, stage by stage (EmbreeAccel's constructor).
    void open_device(const std::string& config);
    RTCScene new_scene(const EmbreeBuildOptions& options) const;
    RTCGeometry new_triangles(const TriangleMesh& mesh, const Transform* to_world);
    void set_vertices(RTCGeometry g, unsigned slot, const std::vector<Vec3>& p,
                      const Transform* to_world);
    void build_object_scenes(const Scene& scene, const std::vector<bool>& flat,
                             const EmbreeBuildOptions& options);
    void attach_flattened(const Scene& scene, uint32_t instance);
    void attach_instance(const Instance& inst, uint32_t instance);

    ~Impl() {
        if (top) rtcReleaseScene(top);
        for (RTCScene s : object_scenes)
            if (s) rtcReleaseScene(s);
        if (device) rtcReleaseDevice(device);
    }
};

static_assert(EmbreeHitMap::kNoInstance == RTC_INVALID_GEOMETRY_ID);

namespace {

// The query's context: Embree passes it to the filter below, which needs the world rays
// (Embree hands it the ray in its own object space).
struct QueryContext {
    RTCIntersectContext embree;
    const Ray* rays;  // indexed by RTCRay::id
    const EmbreeAccel::Impl* impl;
};

void init_context(QueryContext* q, const Ray* rays, const EmbreeAccel::Impl* impl) {
    rtcInitIntersectContext(&q->embree);
    q->rays = rays;
    q->impl = impl;
}

// Embree's t for a triangle and ours (refine) differ by rounding, and on moving
// instances by far more (their interpolated transform carries the approximate reciprocal
// square root's error, ~1e-6 relative, divided by the cosine at the hit: Embree counted a
// shadow ray occluded by a hit 2.2e-4 behind its origin). Where it matters the query
// decides by our t: a candidate counts only where its plane_hit t lies in the ray's
// [tmin, tmax]. It matters for every query in a scene with moving or deforming geometry,
// and for rays that continue past a hit (tmin just above the refined t of the surface
// they pass through, which Embree's own t could still reach again).
void refined_t_filter(const RTCFilterFunctionNArguments* args) {
    const auto* q = reinterpret_cast<const QueryContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        const Ray& ray = q->rays[RTCRayN_id(args->ray, args->N, i)];
        const Hit h = q->impl->hits.hit(
            ray, RTCHitN_instID(args->hit, args->N, i, 0), RTCHitN_geomID(args->hit, args->N, i),
            RTCHitN_primID(args->hit, args->N, i), 0, 0, RTCRayN_tfar(args->ray, args->N, i));
        if (!(h.t >= ray.tmin && h.t <= ray.tmax)) args->valid[i] = 0;
    }
}

// Whether a query needs refined_t_filter (one comparison, as it is asked per ray).
bool needs_filter(const EmbreeAccel::Impl& im, const Ray& ray) {
    return ray.tmin > im.filter_above;
}

}  // namespace

void EmbreeAccel::Impl::open_device(const std::string& config) {
    device = new_device(config);
    rtcSetDeviceErrorFunction(device, error_callback, &errors);
    rtcSetDeviceMemoryMonitorFunction(device, memory_callback, &memory);
}

RTCScene EmbreeAccel::Impl::new_scene(const EmbreeBuildOptions& options) const {
    RTCScene s = rtcNewScene(device);
    // The default (Moeller-Trumbore) triangle test is not watertight: rays from inside a
    // closed 64k-triangle sphere, aimed at its vertices and edges, missed 521 times in
    // 6000 (tests/core/accel/bvh_accel_test.cpp, Watertight). ROBUST selects the
    // watertight Pluecker test and conservative traversal. CONTEXT_FILTER_FUNCTION:
    // queries may carry refined_t_filter.
    const int flags = RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION |
                      (options.compact ? RTC_SCENE_FLAG_COMPACT : 0);
    rtcSetSceneFlags(s, RTCSceneFlags(flags));
    rtcSetSceneBuildQuality(
        s, options.quality == EmbreeBuildOptions::Quality::Low    ? RTC_BUILD_QUALITY_LOW
           : options.quality == EmbreeBuildOptions::Quality::High ? RTC_BUILD_QUALITY_HIGH
                                                                  : RTC_BUILD_QUALITY_MEDIUM);
    return s;
}

// The scene's arrays are shared, not copied, where they allow it: Embree reads the last
// vertex with a 16-byte load (rtcSetSharedGeometryBuffer(3)), so a vertex array needs a
// spare element of capacity (io/ reserves one). Other arrays are copied into Embree's
// own, padded buffers.
void EmbreeAccel::Impl::set_vertices(RTCGeometry g, unsigned slot, const std::vector<Vec3>& p,
                                     const Transform* to_world) {
    if (!to_world && p.capacity() > p.size()) {
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, slot, RTC_FORMAT_FLOAT3, p.data(), 0,
                                   sizeof(Vec3), p.size());
        return;
    }
    auto* v = static_cast<Vec3*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, slot, RTC_FORMAT_FLOAT3, sizeof(Vec3), p.size()));
    if (to_world) {
        // Each vertex is off the exact image by Transform::point's rounding, the error
        // make_surface_point already bounds for its xf.point(q).
        for (size_t i = 0; i < p.size(); ++i) v[i] = to_world->point(p[i]);
    } else {
        std::memcpy(static_cast<void*>(v), p.data(), p.size() * sizeof(Vec3));
    }
    copied_bytes += p.size() * sizeof(Vec3);
}

// A committed triangle geometry of mesh, placed by to_world (nullptr: object space).
RTCGeometry EmbreeAccel::Impl::new_triangles(const TriangleMesh& mesh, const Transform* to_world) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (mesh.motion_positions.empty()) {
        set_vertices(g, 0, mesh.positions, to_world);
    } else {
        // Deformation: one vertex buffer per time step; Embree interpolates linearly
        // between them (motion.h's position_at).
        const auto steps = static_cast<unsigned>(mesh.motion_positions.size());
        rtcSetGeometryTimeStepCount(g, steps);
        for (unsigned k = 0; k < steps; ++k) set_vertices(g, k, mesh.motion_positions[k], to_world);
    }
    // Index loads need no padding.
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.indices.data(),
                               0, 3 * sizeof(uint32_t), mesh.triangle_count());
    rtcCommitGeometry(g);
    return g;
}

// Bottom level: each Object that some instance places (not flattened) once, whatever
// the number of instances.
void EmbreeAccel::Impl::build_object_scenes(const Scene& scene, const std::vector<bool>& flat,
                                            const EmbreeBuildOptions& options) {
    std::vector<bool> needs_scene(scene.objects.size(), false);
    std::vector<bool> moves(scene.objects.size(), false);  // placed by a moving instance
    // Static instanced meshes keep their triangles' planes (HitRefiner::keep_planes) within
    // what flatten_budget leaves after the flattened copies, whose planes it also counts.
    size_t plane_budget = options.flatten_budget;
    for (size_t ii = 0; ii < scene.instances.size(); ++ii) {
        const uint32_t object = scene.instances[ii].object;
        if (!flat[ii]) needs_scene[object] = true;
        if (!scene.instances[ii].motion.empty()) moves[object] = true;
        if (flat[ii])
            for (uint32_t mi : scene.objects[object].meshes)
                plane_budget -= std::min(plane_budget, scene.meshes[mi].triangle_count());
    }
    object_scenes.assign(scene.objects.size(), nullptr);
    for (size_t oi = 0; oi < scene.objects.size(); ++oi) {
        if (!needs_scene[oi]) continue;
        RTCScene s = new_scene(options);
        object_scenes[oi] = s;
        for (uint32_t mesh_index : scene.objects[oi].meshes) {
            const TriangleMesh& mesh = scene.meshes[mesh_index];
            if (moves[oi] || !mesh.motion_positions.empty())
                filter_above = -std::numeric_limits<float>::infinity();
            RTCGeometry g = new_triangles(mesh, nullptr);
            const uint32_t geom_id = rtcAttachGeometry(s, g);
            rtcReleaseGeometry(g);
            const bool keep =
                mesh.motion_positions.empty() && mesh.triangle_count() <= plane_budget;
            if (keep) plane_budget -= mesh.triangle_count();
            hits.add_object_mesh(static_cast<uint32_t>(oi), geom_id, mesh_index, keep);
        }
        rtcCommitScene(s);
        throw_if_error("building an object scene");
    }
}

// A flattened instance: its object's meshes as world-space triangles of the top level.
void EmbreeAccel::Impl::attach_flattened(const Scene& scene, uint32_t instance) {
    const Instance& inst = scene.instances[instance];
    const Transform* world = inst.to_world.matrix().is_identity() ? nullptr : &inst.to_world;
    for (uint32_t mesh_index : scene.objects[inst.object].meshes) {
        RTCGeometry g = new_triangles(scene.meshes[mesh_index], world);
        rtcAttachGeometryByID(top, g, hits.add_flat_mesh(instance, mesh_index, world));
        rtcReleaseGeometry(g);
    }
}

// Any other instance: an instance geometry of its object's scene, geomID = instance
// index (Hit::instance).
void EmbreeAccel::Impl::attach_instance(const Instance& inst, uint32_t instance) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, object_scenes[inst.object]);
    if (inst.motion.empty()) {
        float xfm[12];  // 3x4 column-major
        const Mat4& m = inst.to_world.matrix();
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 3; ++r) xfm[c * 3 + r] = m(r, c);
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
    } else {
        set_transform_steps(g, inst.motion);
    }
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(top, g, instance);
    rtcReleaseGeometry(g);
}

EmbreeAccel::EmbreeAccel(const Scene& scene, const EmbreeBuildOptions& options)
    : m_impl(std::make_unique<Impl>()) {
    const auto start = std::chrono::steady_clock::now();
    Impl& im = *m_impl;
    im.open_device(options.device_config);
    im.hits = EmbreeHitMap(scene);
    const std::vector<bool> flat = flattened_instances(scene, options);
    im.build_object_scenes(scene, flat, options);
    // Top level: the instances (geomID = instance index), then the flattened meshes.
    im.top = im.new_scene(options);
    for (uint32_t ii = 0; ii < scene.instances.size(); ++ii) {
        if (flat[ii]) {
            im.attach_flattened(scene, ii);
            ++m_flattened;
        } else {
            im.attach_instance(scene.instances[ii], ii);
        }
    }
    rtcCommitScene(im.top);
    im.throw_if_error("building the top-level scene");

    m_copied_bytes = im.copied_bytes;
    m_facet_bytes = im.hits.record_bytes();
    m_stats.name = "embree";
    m_stats.build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m_stats.object_scenes = static_cast<size_t>(std::count_if(
        im.object_scenes.begin(), im.object_scenes.end(), [](RTCScene s) { return s != nullptr; }));
    m_stats.instances = scene.instances.size() - m_flattened;
    m_stats.memory_bytes = static_cast<size_t>(std::max<int64_t>(0, im.memory.load())) +
                           m_facet_bytes + im.hits.kept_plane_bytes();
}

EmbreeAccel::~EmbreeAccel() = default;

void EmbreeAccel::rebind(const Scene& scene) { m_impl->hits.rebind(scene); }

namespace {

void fill_ray(const Ray& ray, RTCRay& r) {
    r.org_x = ray.o.x;
    r.org_y = ray.o.y;
    r.org_z = ray.o.z;
    r.dir_x = ray.d.x;
    r.dir_y = ray.d.y;
    r.dir_z = ray.d.z;
    r.tnear = ray.tmin;
    r.tfar = ray.tmax;
    r.time = ray.time;
    r.mask = 0xffffffffu;
    r.id = 0;
    r.flags = 0;
}

}  // namespace

std::optional<Hit> EmbreeAccel::do_intersect(const Ray& ray) const {
    return closest_hit(ray, needs_filter(*m_impl, ray));
}

// Unfiltered, the refined t of Embree's closest hit can still fall outside [tmin, tmax]
// where Embree's own t was inside by its rounding (a hit within rounding of the origin):
// the query is then asked again with the filter, which rejects that candidate, so a
// reported hit always lies in the ray's interval by our t.
std::optional<Hit> EmbreeAccel::closest_hit(const Ray& ray, bool filtered) const {
    RTCRayHit rh;
    fill_ray(ray, rh.ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    if (filtered) {
        QueryContext ctx;
        init_context(&ctx, &ray, m_impl.get());
        ctx.embree.filter = refined_t_filter;
        rtcIntersect1(m_impl->top, &ctx.embree, &rh);
    } else {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        rtcIntersect1(m_impl->top, &ctx, &rh);
    }
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    const Hit h = m_impl->hits.hit(ray, rh.hit.instID[0], rh.hit.geomID, rh.hit.primID, rh.hit.u,
                                   rh.hit.v, rh.ray.tfar);
    if (!filtered && !(h.t >= ray.tmin && h.t <= ray.tmax)) return closest_hit(ray, true);
    return h;
}

bool EmbreeAccel::do_occluded(const Ray& ray) const {
    RTCRay r;
    fill_ray(ray, r);
    if (needs_filter(*m_impl, ray)) {
        QueryContext ctx;
        init_context(&ctx, &ray, m_impl.get());
        ctx.embree.filter = refined_t_filter;
        rtcOccluded1(m_impl->top, &ctx.embree, &r);
    } else {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        rtcOccluded1(m_impl->top, &ctx, &r);
    }
    return r.tfar == -std::numeric_limits<float>::infinity();
}

void EmbreeAccel::intersect8(const Ray (&rays)[8], std::optional<Hit> (&hits)[8]) const {
    count_rays(8);
    QueryContext ctx;
    init_context(&ctx, rays, m_impl.get());
    ctx.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(32) int valid[8];
    alignas(32) RTCRayHit8 rh;
    for (int i = 0; i < 8; ++i) {
        valid[i] = is_traceable(rays[i]) ? -1 : 0;
        if (valid[i] && needs_filter(*m_impl, rays[i])) ctx.embree.filter = refined_t_filter;
        Ray safe;
        safe.d = {0, 0, 1};
        const Ray& r = valid[i] ? rays[i] : safe;
        rh.ray.org_x[i] = r.o.x;
        rh.ray.org_y[i] = r.o.y;
        rh.ray.org_z[i] = r.o.z;
        rh.ray.dir_x[i] = r.d.x;
        rh.ray.dir_y[i] = r.d.y;
        rh.ray.dir_z[i] = r.d.z;
        rh.ray.tnear[i] = r.tmin;
        rh.ray.tfar[i] = r.tmax;
        rh.ray.time[i] = r.time;
        rh.ray.mask[i] = 0xffffffffu;
        rh.ray.id[i] = i;
        rh.ray.flags[i] = 0;
        rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect8(valid, m_impl->top, &ctx.embree, &rh);
    for (int i = 0; i < 8; ++i) {
        if (!valid[i] || rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) {
            hits[i].reset();
            continue;
        }
        const Hit h = m_impl->hits.hit(rays[i], rh.hit.instID[0][i], rh.hit.geomID[i],
                                       rh.hit.primID[i], rh.hit.u[i], rh.hit.v[i], rh.ray.tfar[i]);
        if (!ctx.embree.filter && !(h.t >= rays[i].tmin && h.t <= rays[i].tmax))
            hits[i] = closest_hit(rays[i], true);  // as in closest_hit
        else
            hits[i] = h;
    }
}

void EmbreeAccel::occluded_stream(const Ray* rays, size_t n, bool* occluded, bool coherent) const {
    QueryContext ctx;
    init_context(&ctx, rays, m_impl.get());
    ctx.embree.flags =
        coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    constexpr size_t kChunk = 256;
    RTCRay buffer[kChunk];
    for (size_t start = 0; start < n; start += kChunk) {
        const size_t m = std::min(kChunk, n - start);
        ctx.rays = rays + start;
        for (size_t i = 0; i < m; ++i) {
            fill_ray(rays[start + i], buffer[i]);
            // An untraceable ray becomes an empty interval, which Embree skips.
            if (!is_traceable(rays[start + i])) {
                Ray safe;
                safe.d = {0, 0, 1};
                safe.tmin = 1;
                safe.tmax = 0;
                fill_ray(safe, buffer[i]);
            }
            buffer[i].id = static_cast<unsigned>(i);
            if (needs_filter(*m_impl, rays[start + i])) ctx.embree.filter = refined_t_filter;
        }
        rtcOccluded1M(m_impl->top, &ctx.embree, buffer, unsigned(m), sizeof(RTCRay));
        for (size_t i = 0; i < m; ++i)
            occluded[start + i] = buffer[i].tfar == -std::numeric_limits<float>::infinity();
    }
}

}  // namespace penumbra
