#include "study/accel_check.h"

#include <gtest/gtest.h>

#include <atomic>

#include "core/accel/bvh_accel.h"
#include "support/accel_scenes.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

// Wraps an accelerator and corrupts one answer in `every`: a way to check that the
// checker notices faults and calls them "other".
class FaultyAccel final : public Accel {
public:
    enum class Fault { DropHit, WrongPrim, ShiftT };
    FaultyAccel(const Accel& inner, Fault fault, int every)
        : m_inner(inner), m_fault(fault), m_every(every) {}
    AccelStats stats() const override { return m_inner.stats(); }

protected:
    std::optional<Hit> do_intersect(const Ray& ray) const override {
        std::optional<Hit> h = m_inner.intersect(ray);
        if (!h || (m_count++ % m_every) != 0) return h;
        switch (m_fault) {
            case Fault::DropHit:
                return std::nullopt;
            case Fault::WrongPrim:
                h->prim ^= 1;
                break;
            case Fault::ShiftT:
                h->t *= 1.001f;
                break;
        }
        return h;
    }
    bool do_occluded(const Ray& ray) const override { return m_inner.occluded(ray); }

private:
    const Accel& m_inner;
    Fault m_fault;
    int m_every;
    mutable std::atomic<int> m_count{0};
};

TEST(AccelCheck, DetectsInjectedFaults) {
    const Scene& scene = test::cornell_box();
    const BvhAccel bvh(scene);
    const std::vector<CheckRay> rays = make_random_rays(scene, 20000, 3);
    const TraceResults reference = trace_rays(bvh, rays);
    // The same accelerator agrees with itself exactly.
    const AgreementReport self =
        compare_results(scene, rays, reference, trace_rays(bvh, rays), "bvh", "bvh");
    EXPECT_EQ(self.disagreements(), 0u);
    EXPECT_TRUE(self.passes(0));
    for (auto fault :
         {FaultyAccel::Fault::DropHit, FaultyAccel::Fault::WrongPrim, FaultyAccel::Fault::ShiftT}) {
        const FaultyAccel faulty(bvh, fault, 100);
        const AgreementReport rep =
            compare_results(scene, rays, reference, trace_rays(faulty, rays), "bvh", "faulty");
        // About 1% of the hits are corrupted; nearly all must be flagged "other" (a few
        // land near an edge, on a coincident face or at a grazing angle by chance).
        EXPECT_GT(rep.count(Disagreement::Other), 100u) << static_cast<int>(fault);
        EXPECT_FALSE(rep.passes(1.0));
        EXPECT_FALSE(rep.examples.empty());
    }
}

TEST(AccelCheck, ClassifiesCoincidentEdgeAndGrazingHits) {
    Scene scene;
    // Two identical quads (coincident faces) and, beside them, one quad whose diagonal is
    // a shared edge between its two triangles.
    const uint32_t q = test::add_quad_object(scene, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, -1);
    test::add_instance(scene, q, Transform());
    test::add_instance(scene, q, Transform());
    Ray r;
    r.o = {0.3f, 0.6f, 1};
    r.d = {0, 0, -1};
    Hit a{1, 0, 0, 1, 0.1f, 0.2f}, b{1, 1, 0, 1, 0.1f, 0.2f};
    // add_quad_object: triangles (0,1,2) and (0,2,3); (0.3, 0.6) is inside triangle 1.
    a.b1 = 0.3f;  // not used for the class; only their min barycentric and t matter
    a.b2 = 0.3f;
    b.b1 = 0.3f;
    b.b2 = 0.3f;
    EXPECT_EQ(classify_hits(scene, r, a, a), Disagreement::None);
    EXPECT_EQ(classify_hits(scene, r, a, b), Disagreement::Coincident);
    // The ray through the shared diagonal: triangle 0 and triangle 1 at the same t.
    Ray diag;
    diag.o = {0.5f, 0.5f, 1};
    diag.d = {0, 0, -1};
    Hit d0{1, 0, 0, 0, 0.0f, 0.5f}, d1{1, 0, 0, 1, 0.5f, 0.0f};
    EXPECT_EQ(classify_hits(scene, diag, d0, d1), Disagreement::EdgeOrVertex);
    // Hit versus miss: near an edge, grazing, or else "other".
    EXPECT_EQ(classify_hits(scene, diag, d0, std::nullopt), Disagreement::EdgeOrVertex);
    Ray graze;
    graze.o = {-0.7f, 0.8f, 1e-4f};  // meets z = 0 at (0.3, 0.8), inside triangle 1
    graze.d = {1, 0, -1e-4f};
    Hit g{1, 0, 0, 1, 0.3f, 0.3f};
    EXPECT_EQ(classify_hits(scene, graze, g, std::nullopt), Disagreement::Grazing);
    EXPECT_EQ(classify_hits(scene, r, a, std::nullopt), Disagreement::Other);
    // Same triangle, t off by 1e-3 relative: other; by 1e-6: agreement.
    Hit far = a;
    far.t = 1.001f;
    EXPECT_EQ(classify_hits(scene, r, a, far), Disagreement::Other);
    far.t = 1.000001f;
    EXPECT_EQ(classify_hits(scene, r, a, far), Disagreement::None);
}

// Only disagreements that could be the tested accelerator's fault count: coincident
// faces, and edge cases that double precision settles in its favour, do not.
TEST(AccelCheck, ThresholdCountsOnlyWhatCouldBeTheTestedAcceleratorsFault) {
    AgreementReport rep;
    rep.rays = 100000;
    rep.per_class[static_cast<int>(Disagreement::None)] = 100000 - 5;
    rep.per_class[static_cast<int>(Disagreement::Coincident)] = 2;
    rep.per_class[static_cast<int>(Disagreement::EdgeOrVertex)] = 3;
    rep.edge_test_right = 3;  // the reference was wrong each time
    EXPECT_EQ(rep.disagreements(), 5u);
    EXPECT_EQ(rep.counted(), 0u);
    EXPECT_TRUE(rep.passes(1e-5));
    rep.edge_test_right = 1;
    rep.edge_reference_right = 2;  // the tested accelerator was wrong twice
    EXPECT_EQ(rep.counted(), 2u);
    EXPECT_FALSE(rep.passes(1e-5));
    EXPECT_TRUE(rep.passes(2e-5));
}

}  // namespace
}  // namespace penumbra
