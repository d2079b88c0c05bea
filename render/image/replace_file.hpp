// Replacing a file by bytes already in memory, atomically and checked: the
// only place image output touches the file system (write.cpp encodes every
// format into memory first, so no library writes, or fails to check a
// write, on its own).
#pragma once
#include <cstddef>
#include <string>

namespace kerf::render {

// Writes `size` bytes to a new file in `target`'s folder, checks every
// write(2), fsync(2) and close(2), then renames it over `target`. Returns
// an empty string on success, else the cause ("no space left on device");
// then `target` is untouched and no temporary file remains. The bytes go to
// an anonymous file (O_TMPFILE) that gets a name only for the rename, so a
// render killed while writing, even by SIGKILL, leaves nothing behind; on
// file systems without O_TMPFILE a named temporary is used and removed
// again on SIGHUP, SIGINT, SIGQUIT, SIGTERM and SIGXFSZ (signals whose
// action was the default; the process then ends by the signal as before).
std::string replace_file(const std::string& target, const void* data, std::size_t size);

// Whether replace_file() may create a file in `target`'s folder
// (permissions, read-only mounts): creates one and removes it. Returns an
// empty string or the cause.
std::string probe_folder(const std::string& target);

// strerror(err) as it reads inside a message: "no space left on device".
std::string errno_text(int err);

}  // namespace kerf::render
