// import() of meshes: file reading (bounded: the size is checked before reading),
// dispatch by extension, validation shared by all formats, and the turn into
// OpenSCAD's clockwise face order.
#include "interpreter/import/mesh_import.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "interpreter/import/formats.hpp"

namespace kerf::eval {

namespace mesh_format {

std::size_t line_of(std::string_view bytes, std::size_t at) {
    at = std::min(at, bytes.size());
    return 1 + static_cast<std::size_t>(std::count(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

std::string_view Tokens::next() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    last_ = pos_;
    while (pos_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    return s_.substr(last_, pos_ - last_);
}

void Tokens::expect(std::string_view word) {
    std::string_view t = next();
    if (t != word) fail("expected '" + std::string(word) + "', got " + quoted(t));
}

std::string Tokens::quoted(std::string_view token) {
    return token.empty() ? std::string("the end of the file") : "'" + std::string(token.substr(0, 40)) + "'";
}

double Tokens::number(const char* what) {
    std::string_view t = next();
    double v = 0;
    if (!parse_number(t, v)) fail(std::string("expected ") + what + ", got " + quoted(t));
    return v;
}

void Tokens::skip_line() {
    while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
}

bool Tokens::at_end() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    return pos_ >= s_.size();
}

void Tokens::fail(const std::string& message) const {
    throw MeshFormatError("line " + std::to_string(line_of(s_, last_)) + ": " + message);
}

void Tokens::fail_limit(const std::string& message) const {
    throw MeshLimitError("line " + std::to_string(line_of(s_, last_)) + ": " + message);
}

std::optional<Tokens> Lines::next() {
    while (pos_ < s_.size()) {
        std::size_t eol = s_.find('\n', pos_);
        if (eol == std::string_view::npos) eol = s_.size();
        std::string_view line = s_.substr(pos_, eol - pos_);
        if (std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        Tokens t(s_.substr(0, pos_ + line.size()), pos_);
        pos_ = eol + 1;
        if (!Tokens(t).at_end()) return t;
    }
    return std::nullopt;
}

Tokens Lines::need(const char* what) {
    if (std::optional<Tokens> t = next()) return *t;
    Tokens(s_, s_.size()).fail(std::string("expected ") + what + ", got the end of the file");
}

void check_count(std::uint64_t count, std::uint64_t bytes_left, std::size_t min_bytes, const std::string& what,
                 std::uint64_t limit, std::uint64_t slack) {
    if (count > limit)
        throw MeshLimitError("the file declares " + std::to_string(count) + " " + what + ", more than the limit " +
                              std::to_string(limit) + " (--max-list)");
    if (count > (bytes_left + slack) / min_bytes)
        throw MeshFormatError("the file declares " + std::to_string(count) + " " + what + " but only " +
                              std::to_string(bytes_left) + " bytes follow (truncated?)");
}

namespace {

[[noreturn]] void io_failure(const char* what, int err) {
    throw MeshFormatError(std::string(what) + " the file: " + std::strerror(err));
}

// Closes the descriptor unless released: the constructor below may throw.
struct FdGuard {
    int fd;
    ~FdGuard() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

MeshFile::MeshFile(const std::string& path) {
    FdGuard guard{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
    if (guard.fd < 0) io_failure("cannot open", errno);
    struct stat st {};
    if (::fstat(guard.fd, &st) != 0) io_failure("cannot open", errno);
    // (import() finds only regular files; this one may have been swapped since.)
    if (!S_ISREG(st.st_mode)) throw MeshFormatError("not a regular file");
    size_ = static_cast<std::uint64_t>(st.st_size);
    if (size_ > kMaxImportBytes)
        throw MeshLimitError("longer than " + std::to_string(kMaxImportBytes >> 20) + " MiB (" +
                              std::to_string(size_) + " bytes), too large to import");
    std::swap(fd_, guard.fd);
}

MeshFile::~MeshFile() {
    if (fd_ >= 0) ::close(fd_);
}

void MeshFile::read_exact(std::uint64_t offset, char* out, std::size_t n) const {
    if (offset > size_ || n > size_ - offset)
        throw MeshFormatError("byte " + std::to_string(size_) + ": the file ends inside the data (truncated?)");
    for (std::size_t done = 0; done < n;) {
        const ssize_t got = ::pread(fd_, out + done, n - done, static_cast<off_t>(offset + done));
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) io_failure("cannot read", errno);
        if (got == 0)
            throw MeshFormatError("byte " + std::to_string(offset + done) +
                                  ": the file ended early (did it change while being read?)");
        done += static_cast<std::size_t>(got);
    }
}

std::string MeshFile::read(std::uint64_t offset, std::size_t n) const {
    if (offset >= size_) return {};
    std::string bytes(static_cast<std::size_t>(std::min<std::uint64_t>(n, size_ - offset)), '\0');
    read_exact(offset, bytes.data(), bytes.size());
    return bytes;
}

}  // namespace mesh_format

namespace {

void validate(const graph::PolygonMesh& m) {
    if (m.faces.empty()) throw MeshFormatError("the file holds no faces");
    for (const glm::dvec3& p : m.points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw MeshFormatError("a vertex is not finite");
    std::size_t fi = 0;
    for (const auto& f : m.faces) {
        if (f.size() < 3) throw MeshFormatError("face " + std::to_string(fi) + " has fewer than 3 corners");
        for (std::uint32_t i : f)
            if (i >= m.points.size())
                throw MeshFormatError("face " + std::to_string(fi) + " refers to vertex " + std::to_string(i) +
                                      " (there are " + std::to_string(m.points.size()) + ")");
        ++fi;
    }
}

}  // namespace

ImportedMesh import_mesh(const std::string& path, const MeshReading& how) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    static const char* const kExtensions[] = {".stl", ".obj", ".ply", ".off", ".amf", ".3mf"};
    if (std::none_of(std::begin(kExtensions), std::end(kExtensions), [&](const char* e) { return ext == e; }))
        throw MeshFormatError("unknown mesh format '" + ext + "' (kerf reads .stl, .obj, .ply, .off, .amf and .3mf)");
    const mesh_format::MeshFile file(path);
    ImportedMesh r;
    if (ext == ".amf") r = mesh_format::read_amf(file, path, how);
    else if (ext == ".3mf") r = mesh_format::read_3mf(path, how);
    else
        r.parts.push_back(ext == ".stl"   ? mesh_format::read_stl(file, how.max_faces)
                          : ext == ".ply" ? mesh_format::read_ply(file, how.max_faces)
                          : ext == ".off" ? mesh_format::read_off(file, how.max_faces)
                                          : mesh_format::read_obj(file.read_all(), how.max_faces));
    if (r.parts.empty()) throw MeshFormatError("the file holds no faces");
    for (graph::PolygonMesh& m : r.parts) {
        validate(m);
        for (auto& f : m.faces) std::reverse(f.begin(), f.end());  // counter-clockwise → OpenSCAD's clockwise
    }
    return r;
}

}  // namespace kerf::eval
