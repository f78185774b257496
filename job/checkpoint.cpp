#include "job/checkpoint.h"

#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "io/atomic_file.h"

namespace penumbra {

namespace {

constexpr char kMagic[8] = {'P', 'N', 'B', 'C', 'K', 'P', 'T', '1'};

// FNV-1a over the payload: a file damaged outside our atomic writes (a bad disk, a copy
// cut short) is refused instead of resumed into a wrong image.
uint64_t fnv1a(const void* data, size_t n, uint64_t h = 1469598103934665603ull) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

template <typename T>
void put(std::ofstream& out, uint64_t& h, const T& v) {
    out.write(reinterpret_cast<const char*>(&v), sizeof v);
    h = fnv1a(&v, sizeof v, h);
}
void put_bytes(std::ofstream& out, uint64_t& h, const void* data, size_t n) {
    out.write(static_cast<const char*>(data), std::streamsize(n));
    h = fnv1a(data, n, h);
}
void put_string(std::ofstream& out, uint64_t& h, const std::string& s) {
    put(out, h, uint64_t(s.size()));
    put_bytes(out, h, s.data(), s.size());
}

class Reader {
public:
    explicit Reader(std::ifstream& in) : m_in(in) {}
    bool bytes(void* data, size_t n) {
        if (!m_in.read(static_cast<char*>(data), std::streamsize(n))) return false;
        m_hash = fnv1a(data, n, m_hash);
        return true;
    }
    template <typename T>
    bool get(T& v) {
        return bytes(&v, sizeof v);
    }
    bool string(std::string& s, uint64_t max) {
        uint64_t n = 0;
        if (!get(n) || n > max) return false;
        s.resize(n);
        return bytes(s.data(), n);
    }
    uint64_t hash() const { return m_hash; }

private:
    std::ifstream& m_in;
    uint64_t m_hash = 1469598103934665603ull;
};

}  // namespace

std::string checkpoint_path(const std::string& output) { return output + ".ckpt"; }

void write_checkpoint(const std::string& path, const Film& film, const CheckpointState& state) {
    write_file_atomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        uint64_t h = fnv1a(nullptr, 0);
        out.write(kMagic, sizeof kMagic);
        put_string(out, h, state.fingerprint);
        put(out, h, state.spp);
        put(out, h, state.rays);
        put(out, h, state.seconds);
        put(out, h, int32_t(film.width()));
        put(out, h, int32_t(film.height()));
        const std::vector<Film::Buffer> buffers = film.buffers();
        put(out, h, uint32_t(buffers.size()));
        for (const Film::Buffer& b : buffers) {
            put_string(out, h, b.name);
            put(out, h, uint64_t(b.bytes));
            put_bytes(out, h, b.data, b.bytes);
        }
        out.write(reinterpret_cast<const char*>(&h), sizeof h);
        out.close();
        if (!out) throw SceneError(path + ": cannot write the checkpoint");
    });
}

std::optional<CheckpointState> read_checkpoint(const std::string& path,
                                               const std::string& fingerprint, Film& film,
                                               std::string* why) {
    auto refuse = [&](const std::string& reason) -> std::optional<CheckpointState> {
        if (why) *why = reason;
        return std::nullopt;
    };
    std::ifstream in(path, std::ios::binary);
    if (!in) return refuse("no checkpoint");
    char magic[sizeof kMagic];
    if (!in.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0)
        return refuse(path + ": not a penumbra checkpoint");
    Reader r(in);
    CheckpointState state;
    if (!r.string(state.fingerprint, 1 << 20)) return refuse(path + ": damaged checkpoint");
    if (state.fingerprint != fingerprint)
        return refuse(path + ": the checkpoint is of another scene or other options");
    int32_t w = 0, h = 0;
    uint32_t count = 0;
    if (!r.get(state.spp) || !r.get(state.rays) || !r.get(state.seconds) || !r.get(w) ||
        !r.get(h) || !r.get(count))
        return refuse(path + ": damaged checkpoint");
    const std::vector<Film::Buffer> buffers = film.buffers();
    if (w != film.width() || h != film.height() || count != buffers.size())
        return refuse(path + ": the checkpoint's image size or buffers differ from this render's");
    // Read into a copy: a file damaged half-way must not leave a half-filled film.
    Film loaded(film.width(), film.height(), film.aovs());
    const std::vector<Film::Buffer> into = loaded.buffers();
    for (const Film::Buffer& b : into) {
        std::string name;
        uint64_t bytes = 0;
        if (!r.string(name, 256) || !r.get(bytes)) return refuse(path + ": damaged checkpoint");
        if (name != b.name || bytes != b.bytes)
            return refuse(path + ": the checkpoint's buffer '" + name +
                          "' does not match this render's");
        if (!r.bytes(b.data, b.bytes)) return refuse(path + ": damaged checkpoint");
    }
    uint64_t stored = 0;
    const uint64_t computed = r.hash();
    if (!in.read(reinterpret_cast<char*>(&stored), sizeof stored) || stored != computed)
        return refuse(path + ": damaged checkpoint (checksum)");
    film = std::move(loaded);
    return state;
}

}  // namespace penumbra
