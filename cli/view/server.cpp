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

// The server of server.hpp, on cpp-httplib.
class HttpServer final : public Server {
public:
    HttpServer(const std::string& address, int port, Handlers handlers);
    ~HttpServer() override;
    int port() const override { return port_; }
    std::string url() const override;
    void start() override;
    void publish(const std::string& kind, const std::string& json) override { hub.publish(kind, json); }
    std::uint64_t put_image(std::vector<unsigned char> png) override;

private:
    std::string address;
    int port_ = 0;
    Handlers handlers;
    httplib::Server http;
    EventHub hub{kMaxStreams};
    std::thread thread;
    std::mutex images_mutex;
    std::deque<std::pair<std::uint64_t, std::shared_ptr<const std::vector<unsigned char>>>> images;
    std::uint64_t next_image = 0;

    void routes();
};

HttpServer::HttpServer(const std::string& address, int port, Handlers handlers) {
    if (!is_loopback_address(address))
        throw std::runtime_error("kerf view listens on a loopback address only (127.0.0.1 or ::1), not '" + address + "'");
    this->address = address;
    this->handlers = std::move(handlers);
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
    routes();
    if (port == 0) {
        port_ = http.bind_to_any_port(address);
        if (port_ <= 0) throw std::runtime_error("cannot listen on " + address + ": no free port");
    } else {
        if (!http.bind_to_port(address, port))
            throw std::runtime_error("cannot listen on " + address + " port " + std::to_string(port) +
                                     " (in use, or not permitted)");
        port_ = port;
    }
    if (listening >= 0) ::listen(listening, kBacklog);  // a listening socket takes a new backlog
}

HttpServer::~HttpServer() {
    hub.close();
    http.stop();
    if (thread.joinable()) thread.join();
}

std::string HttpServer::url() const {
    const std::string& a = address;
    return "http://" + (a.find(':') != std::string::npos ? "[" + a + "]" : a) + ":" + std::to_string(port_) + "/";
}

void HttpServer::start() {
    thread = std::thread([this] { http.listen_after_bind(); });
}

std::uint64_t HttpServer::put_image(std::vector<unsigned char> png) {
    std::lock_guard<std::mutex> lock(images_mutex);
    images.emplace_back(++next_image, std::make_shared<const std::vector<unsigned char>>(std::move(png)));
    while (images.size() > kKeptImages) images.pop_front();
    return next_image;
}

void HttpServer::routes() {
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
        if (host_allowed(req.get_header_value("Host"), address, port_) &&
            origin_allowed(req.get_header_value("Origin"), address, port_) &&
            fetch_site_allowed(req.get_header_value("Sec-Fetch-Site")))
            return httplib::Server::HandlerResponse::Unhandled;
        res.status = 403;
        res.set_content("forbidden: this server answers only its own page at http://" + address + ":" +
                            std::to_string(port_) + "/\n",
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

}  // namespace

}  // namespace kerf::view

extern "C" kerf::view::Server* kerf_view_open_server(const std::string& address, int port, kerf::view::Handlers& handlers,
                                                     std::string& error) {
    try {
        return new kerf::view::HttpServer(address, port, std::move(handlers));
    } catch (const std::exception& e) {
        error = e.what();
        return nullptr;
    }
}
