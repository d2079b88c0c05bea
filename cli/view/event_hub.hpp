// The server-sent events of kerf view: the newest message of each kind
// ("image", "diagnostics", "status"), each with a sequence number. A stream
// sends every kind newer than what it sent last, oldest first, so a client
// that connects late gets the current state at once and a slow one skips
// images it would only draw over.
#pragma once
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>

namespace kerf::view {

class EventHub {
public:
    explicit EventHub(int max_streams) : max_streams_(max_streams) {}

    // `data`: one line (JSON), replaces the kind's last message.
    void publish(const std::string& kind, const std::string& data);
    // The SSE text of every kind published after `*seen` (then `*seen` is
    // the newest), waiting up to `timeout` for one; "" on timeout or close.
    std::string next(std::uint64_t* seen, std::chrono::milliseconds timeout);
    // Streams count against max_streams (each holds a server thread).
    bool join();
    void leave();
    // Ends every stream (server shutdown).
    void close();
    bool closed() const;

private:
    struct Message {
        std::uint64_t seq;
        std::string data;
    };
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::map<std::string, Message> latest_;
    std::uint64_t seq_ = 0;
    int streams_ = 0;
    const int max_streams_;
    bool closed_ = false;
};

}  // namespace kerf::view
