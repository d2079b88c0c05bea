#include "cli/view/event_hub.hpp"

#include <algorithm>
#include <vector>

namespace kerf::view {

void EventHub::publish(const std::string& kind, const std::string& data) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        latest_[kind] = Message{++seq_, data};
    }
    changed_.notify_all();
}

std::string EventHub::next(std::uint64_t* seen, std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait_for(lock, timeout, [&] { return closed_ || seq_ > *seen; });
    if (closed_ || seq_ <= *seen) return {};
    std::vector<std::pair<std::uint64_t, std::string>> fresh;
    for (const auto& [kind, m] : latest_)
        if (m.seq > *seen) fresh.emplace_back(m.seq, "event: " + kind + "\ndata: " + m.data + "\n\n");
    std::sort(fresh.begin(), fresh.end());
    std::string out;
    for (const auto& f : fresh) out += f.second;
    *seen = seq_;
    return out;
}

bool EventHub::join() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (closed_ || streams_ >= max_streams_) return false;
    ++streams_;
    return true;
}

void EventHub::leave() {
    std::lock_guard<std::mutex> lock(mutex_);
    --streams_;
}

void EventHub::close() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        closed_ = true;
    }
    changed_.notify_all();
}

bool EventHub::closed() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return closed_;
}

}  // namespace kerf::view
