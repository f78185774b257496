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
// outside) changes nothing; entering beyond kCapacity volumes is ignored. Each entry
// remembers the instance whose surface it entered through (-1: unknown), so that a path
// found outside that instance's bounds can drop it (leave_where).
class MediumStack {
public:
    static constexpr int kCapacity = 8;

    // The material whose interior the path is in: the innermost entry; -1 outside all.
    int current() const { return m_size > 0 ? m_materials[m_size - 1] : -1; }
    int size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    void enter(int material, int instance = -1) {
        if (m_size < kCapacity) {
            m_materials[m_size] = material;
            m_instances[m_size++] = instance;
        }
    }
    void leave(int material) {
        for (int i = m_size - 1; i >= 0; --i)
            if (m_materials[i] == material) {
                remove(i);
                return;
            }
    }
    // Removes every entry whose instance outside(instance) rules out (never -1's).
    template <typename Outside>
    void leave_where(Outside outside) {
        for (int i = m_size - 1; i >= 0; --i)
            if (m_instances[i] >= 0 && outside(m_instances[i])) remove(i);
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
    void remove(int i) {
        for (int j = i; j + 1 < m_size; ++j) {
            m_materials[j] = m_materials[j + 1];
            m_instances[j] = m_instances[j + 1];
        }
        --m_size;
    }

    std::array<int, kCapacity> m_materials{};
    std::array<int, kCapacity> m_instances{};
    int m_size = 0;
};

}  // namespace penumbra
