#include "grammar/parser.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "grammar/actions.hpp"
#include "grammar/errors.hpp"
#include "grammar/text_check.hpp"

namespace kerf {

namespace {
[[noreturn]] void io_error(const std::string& path, int err) {
    throw IoError("cannot open '" + path + "': " + std::strerror(err));
}

// Line and byte column of an offset, counted like PEGTL does.
SourceLoc locate(const std::shared_ptr<const SourceFile>& file, std::string_view text, std::size_t offset) {
    std::uint32_t line = 1, col = 1;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            col = 1;
        } else {
            ++col;
        }
    }
    return SourceLoc{file, line, col};
}
}  // namespace

std::shared_ptr<const SourceFile> read_source_file(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) io_error(path, errno);
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) io_error(path, errno);
    if (S_ISDIR(st.st_mode)) io_error(path, EISDIR);
    auto file = std::make_shared<SourceFile>();
    file->path = path;
    if (S_ISREG(st.st_mode)) file->text.reserve(static_cast<std::size_t>(st.st_size));
    char buf[1 << 16];
    for (;;) {
        const ssize_t got = ::read(fd, buf, sizeof buf);
        if (got < 0) {
            if (errno == EINTR) continue;
            io_error(path, errno);
        }
        if (got == 0) break;
        file->text.append(buf, static_cast<std::size_t>(got));
        // A script is text someone wrote or generated, far below this; a
        // device or pipe that never ends (/dev/zero) must not read forever.
        if (file->text.size() > kMaxSourceBytes)
            throw IoError("cannot read '" + path + "': longer than " + std::to_string(kMaxSourceBytes >> 20) +
                          " MiB, too large for a scene script");
    }
    return file;
}

ast::Program parse_program(std::shared_ptr<const SourceFile> file, const ParseOptions& limits) {
    namespace pg = tao::pegtl;
    std::string_view text = file->text;
    // A UTF-8 byte order mark is not part of the script (columns start after it).
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    if (const auto bad = grammar::find_invalid_byte(text, limits.openscad); bad != std::string_view::npos)
        throw SourceError(locate(file, text, bad), "invalid character");

    grammar::Builder builder(file, limits.max_nesting);
    builder.openscad = limits.openscad;
    pg::memory_input<pg::tracking_mode::eager, pg::eol::lf_crlf> in(text.data(), text.size(), file->path);
    try {
        pg::parse<grammar::program, grammar::action, grammar::control>(in, builder);
    } catch (const pg::parse_error& e) {
        const auto& positions = e.positions();
        SourceLoc at{file, 0, 0};
        if (!positions.empty()) at = builder.loc(positions.front().line, positions.front().column);
        // A `;` is missing where the statement ends, before the blank lines
        // and comments that follow it (`x = 1` then `y = 2;` on the next
        // line); a stray token on the same line is itself the place (`1 × 2`).
        const std::string message(e.message());
        if (message == "expected ';'" && !positions.empty() && builder.gap_end &&
            builder.gap_end == text.data() + positions.front().byte &&
            std::string_view(builder.gap_begin, static_cast<std::size_t>(builder.gap_end - builder.gap_begin))
                    .find('\n') != std::string_view::npos)
            at = locate(file, text, static_cast<std::size_t>(builder.gap_begin - text.data()));
        throw SourceError(std::move(at), message);
    }
    return builder.finish();
}

}  // namespace kerf
