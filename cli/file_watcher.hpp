// Watching a set of files for changes with inotify (Linux), for `kerf watch`.
// Each file's folder is watched, not the file's inode: editors that save by
// writing a new file and renaming it over the old one (Vim, most IDEs)
// replace the inode, and a file that does not exist yet (an include being
// written) can appear. Events are matched by name against the set.
#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace kerf::cli {

class FileWatcher {
public:
    FileWatcher();  // throws std::runtime_error when inotify is unavailable
    ~FileWatcher();
    FileWatcher(const FileWatcher&) = delete;
    FileWatcher& operator=(const FileWatcher&) = delete;

    // Watches exactly `paths` from now on (a symlink: also its target).
    // A folder that does not exist cannot be watched and is skipped.
    void watch(const std::vector<std::string>& paths);
    // Waits up to `timeout_ms` (-1: for ever) for a change to a watched
    // file; true when one came. Reads every event already queued.
    bool wait(int timeout_ms);
    // The first watched file seen changed since the last call ("" if none).
    std::string take_changed() { return std::exchange(changed_, std::string()); }
    // After a change: waits until the files have been quiet for `quiet_ms`
    // (a burst of saves is one change), but no longer than `longest_ms` (a
    // file written without pause still gets rendered).
    void settle(int quiet_ms, int longest_ms);

private:
    bool read_events();  // true when a queued event names a watched file

    int fd_;
    std::string changed_;
    std::map<int, std::string> dirs_;                // watch descriptor -> folder
    // folder -> watched names in it -> the path as watch() was given it
    std::map<std::string, std::map<std::string, std::string>> names_;
};

}  // namespace kerf::cli
