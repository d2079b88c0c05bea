#include "csg/texture.hpp"

#include <atomic>

namespace kerf::csg {

namespace {
std::atomic<TextureReader> g_reader{nullptr};
}

void set_texture_reader(TextureReader reader) { g_reader.store(reader); }
TextureReader texture_reader() { return g_reader.load(); }

}  // namespace kerf::csg
