// Which volumes a path is inside: a small stack of the materials whose closed meshes it
// has entered and not yet left (Mitsuba's medium stack; pbrt-v4's MediumInterface keeps
// one medium per side instead, which cannot nest).
#pragma once

#include <array>

namespace penumbra {

// Nesting (liquid in a glass): entering pushes, leaving removes, so the path is in the
// innermost volume it entered last. Overlap (two volumes sharing space, left in any
// order): the region inside both takes the medium entered last, and leaving removes
// that material's own innermost entry wherever it sits. Leaving a volume the path is
// not in (camera rays start outside all media, so a camera inside a volume sees it as
// outside) changes nothing; entering beyond kCapacity volumes is ignored.
class MediumStack {
public:
    static constexpr int kCapacity = 8;

    // The material whose interior the path is in: the innermost entry; -1 outside all.
    int current() const { return m_size > 0 ? m_materials[m_size - 1] : -1; }
    int size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    void enter(int material) {
        if (m_size < kCapacity) m_materials[m_size++] = material;
    }
    void leave(int material) {
        for (int i = m_size - 1; i >= 0; --i)
            if (m_materials[i] == material) {
                for (int j = i; j + 1 < m_size; ++j) m_materials[j] = m_materials[j + 1];
                --m_size;
                return;
            }
    }
    bool contains(int material) const {
        for (int i = 0; i < m_size; ++i)
            if (m_materials[i] == material) return true;
        return false;
    }
    // The material entered just outside the innermost one: the medium beyond the surface
    // of the innermost volume; -1 when that is the outside of everything.
    int enclosing() const { return m_size > 1 ? m_materials[m_size - 2] : -1; }

private:
    std::array<int, kCapacity> m_materials{};
    int m_size = 0;
};

}  // namespace penumbra
