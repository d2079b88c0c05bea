#include "cli/view/server.hpp"

#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>

#include <httplib.h>
#include <sys/socket.h>

#include "cli/view/camera_text.hpp"
#include "cli/view/event_hub.hpp"
#include "cli/view/guard.hpp"
#include "cli/view/page.hpp"

namespace kerf::view {

namespace {

// Each connection holds one of these threads while it is read and answered,
// an event stream for as long as its page is open: a few pages, and enough
// left over that a handful of stalled clients cannot lock the page out.
constexpr int kThreads = 32;
constexpr int kMaxStreams = 8;
constexpr int kKeptImages = 8;           // a page fetching an image just replaced still gets it
constexpr std::size_t kMaxBody = 1 << 16;  // the page sends only short queries
// cpp-httplib listens with a backlog of 5: a burst of connections (a page
// fetching while a script polls) would wait for SYN retransmits, seconds.
constexpr int kBacklog = 1024;

}  // namespace

struct Server::Impl {
    std::string address;
    int port = 0;
    Handlers handlers;
    httplib::Server http;
    EventHub hub{kMaxStreams};
    std::thread thread;
    std::mutex images_mutex;
    std::deque<std::pair<std::uint64_t, std::shared_ptr<const std::vector<unsigned char>>>> images;
    std::uint64_t next_image = 0;

    void routes();
};

Server::Server(const std::string& address, int port, Handlers handlers) : impl_(std::make_unique<Impl>()) {
    if (!is_loopback_address(address))
        throw std::runtime_error("kerf view listens on a loopback address only (127.0.0.1 or ::1), not '" + address + "'");
    impl_->address = address;
    impl_->handlers = std::move(handlers);
    httplib::Server& http = impl_->http;
    http.new_task_queue = [] { return new httplib::ThreadPool(kThreads); };
    // A client that stops sending frees its thread after this long.
    http.set_read_timeout(1, 0);
    http.set_write_timeout(3, 0);
    http.set_keep_alive_timeout(2);
    http.set_payload_max_length(kMaxBody);
    if (address.find(':') != std::string::npos) http.set_address_family(AF_INET6);
    // Instead of cpp-httplib's default SO_REUSEPORT, which would let a
    // second process bind the same port and take a share of the requests:
    // SO_REUSEADDR only (a restart may reuse the port at once).
    int listening = -1;
    http.set_socket_options([&listening](int fd) {
        int yes = 1;
        ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
        listening = fd;
    });
    impl_->routes();
    if (port == 0) {
        impl_->port = http.bind_to_any_port(address);
        if (impl_->port <= 0) throw std::runtime_error("cannot listen on " + address + ": no free port");
    } else {
        if (!http.bind_to_port(address, port))
            throw std::runtime_error("cannot listen on " + address + " port " + std::to_string(port) +
                                     " (in use, or not permitted)");
        impl_->port = port;
    }
    if (listening >= 0) ::listen(listening, kBacklog);  // a listening socket takes a new backlog
}

Server::~Server() {
    impl_->hub.close();
    impl_->http.stop();
    if (impl_->thread.joinable()) impl_->thread.join();
}

int Server::port() const { return impl_->port; }

std::string Server::url() const {
    const std::string& a = impl_->address;
    return "http://" + (a.find(':') != std::string::npos ? "[" + a + "]" : a) + ":" + std::to_string(impl_->port) + "/";
}

void Server::start() {
    impl_->thread = std::thread([this] { impl_->http.listen_after_bind(); });
}

void Server::publish(const std::string& kind, const std::string& json) { impl_->hub.publish(kind, json); }

std::uint64_t Server::put_image(std::vector<unsigned char> png) {
    std::lock_guard<std::mutex> lock(impl_->images_mutex);
    impl_->images.emplace_back(++impl_->next_image, std::make_shared<const std::vector<unsigned char>>(std::move(png)));
    while (impl_->images.size() > kKeptImages) impl_->images.pop_front();
    return impl_->next_image;
}

void Server::Impl::routes() {
    using httplib::Request;
    using httplib::Response;
    // Every answer: not cached, not framed by another page, never sniffed
    // into another type, scripts and images from this server only.
    http.set_default_headers({
        {"Cache-Control", "no-store"},
        {"X-Content-Type-Options", "nosniff"},
        {"X-Frame-Options", "DENY"},
        {"Referrer-Policy", "no-referrer"},
        {"Content-Security-Policy",
         "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; img-src 'self' blob:; connect-src 'self'; "
         "frame-ancestors 'none'"},
    });
    http.set_pre_routing_handler([this](const Request& req, Response& res) {
        if (host_allowed(req.get_header_value("Host"), address, port) &&
            origin_allowed(req.get_header_value("Origin"), address, port) &&
            fetch_site_allowed(req.get_header_value("Sec-Fetch-Site")))
            return httplib::Server::HandlerResponse::Unhandled;
        res.status = 403;
        res.set_content("forbidden: this server answers only its own page at http://" + address + ":" +
                            std::to_string(port) + "/\n",
                        "text/plain");
        return httplib::Server::HandlerResponse::Handled;
    });
    http.set_error_handler([](const Request&, Response& res) {
        if (res.body.empty()) res.set_content(std::to_string(res.status) + "\n", "text/plain");
    });
    http.set_exception_handler([](const Request&, Response& res, std::exception_ptr) {
        res.status = 500;
        res.set_content("internal error\n", "text/plain");
    });

    http.Get("/", [](const Request&, Response& res) { res.set_content(page_html(), "text/html; charset=utf-8"); });
    http.Get("/events", [this](const Request&, Response& res) {
        if (!hub.join()) {
            res.status = 503;
            res.set_content("too many open pages\n", "text/plain");
            return;
        }
        auto seen = std::make_shared<std::uint64_t>(0);
        res.set_chunked_content_provider(
            "text/event-stream",
            [this, seen](std::size_t, httplib::DataSink& sink) {
                if (hub.closed()) return false;
                std::string text = hub.next(seen.get(), std::chrono::milliseconds(1000));
                // A comment every second when nothing happens: a closed page
                // is noticed (the write fails) and its thread freed.
                if (text.empty()) text = ": idle\n\n";
                return sink.write(text.data(), text.size());
            },
            [this](bool) { hub.leave(); });
    });
    http.Get(R"(/image/(\d{1,19})\.png)", [this](const Request& req, Response& res) {
        const std::uint64_t id = std::stoull(req.matches[1].str());
        std::shared_ptr<const std::vector<unsigned char>> png;
        {
            std::lock_guard<std::mutex> lock(images_mutex);
            for (const auto& [i, bytes] : images)
                if (i == id) png = bytes;
        }
        if (!png) {
            res.status = 404;
            return;
        }
        res.set_content(reinterpret_cast<const char*>(png->data()), png->size(), "image/png");
    });
    http.Post("/camera", [this](const Request& req, Response& res) {
        std::multimap<std::string, std::string> params(req.params.begin(), req.params.end());
        std::string error;
        const auto camera = camera_from_query(params, &error);
        if (!camera) {
            res.status = 400;
            res.set_content(error + "\n", "text/plain");
            return;
        }
        if (handlers.camera) handlers.camera(*camera);
        res.status = 204;
    });
    http.Post("/reset", [this](const Request&, Response& res) {
        if (handlers.reset) handlers.reset();
        res.status = 204;
    });
}

}  // namespace kerf::view
