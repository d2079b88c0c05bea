#include "cli/view_session.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cli/file_watcher.hpp"
#include "cli/pipeline.hpp"
#include "cli/report.hpp"
#include "cli/view/camera_text.hpp"
#include "cli/view/json.hpp"
#include "cli/view/server.hpp"
#include "render/image/png_file.hpp"

namespace kerf::cli {

namespace {

using Clock = std::chrono::steady_clock;

// The same debounce as kerf watch (docs/editors.md).
constexpr int kQuietMs = 100;
constexpr int kLongestMs = 1000;
// The preview is this many times smaller on each side: a sixteenth of the
// rays, so it arrives while the mouse still moves.
constexpr int kPreviewDivisor = 4;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

bool same_camera(const csg::Camera& a, const csg::Camera& b) {
    return a.position == b.position && a.look_at == b.look_at && a.up == b.up && a.fov == b.fov &&
           a.orthographic == b.orthographic && a.height == b.height && a.projection == b.projection &&
           a.aperture == b.aperture && a.focal_distance == b.focal_distance && a.blur_samples == b.blur_samples;
}

// What the render thread is asked to do next; requests that arrive while
// it renders merge into one (the newest scene, the newest camera).
struct Work {
    std::shared_ptr<csg::Scene> scene;  // a newly evaluated scene
    std::optional<csg::Camera> camera;  // the page moved the view
    bool reset = false;                 // back to the scene's camera
    Clock::time_point since;            // the oldest request merged in
};

class Session {
public:
    explicit Session(const Options& o) : o_(o) {}

    int run() {
        try {
            server_ = view::open_server(
                o_.host, o_.port,
                view::Handlers{[this](const csg::Camera& c) { ask([&](Work& w) { w.camera = c; }, Clock::now()); },
                               [this] { ask([](Work& w) { w.reset = true; w.camera.reset(); }, Clock::now()); }});
        } catch (const std::exception& e) {
            std::fprintf(stderr, "kerf: error: %s\n", e.what());
            return kUsage;
        }
        server_->start();
        std::printf("kerf view: %s shows %s (Ctrl-C stops)\n", server_->url().c_str(), o_.scene.c_str());
        std::fflush(stdout);
        FileWatcher watcher;  // throws before any thread starts when inotify is missing
        status("evaluating");
        std::thread renderer([this] { render_loop(); });
        renderer.detach();  // ends with the process (a signal), like kerf watch
        watch_loop(watcher);
        return kOk;
    }

private:
    void status(const std::string& text) {
        server_->publish("status", "{\"text\":" + view::json_string(text) + ",\"scene\":" + view::json_string(o_.scene) + "}");
    }

    void diagnostics(bool error, const std::string& text) {
        server_->publish("diagnostics", std::string("{\"error\":") + (error ? "true" : "false") +
                                            ",\"text\":" + view::json_string(text) + "}");
    }

    template <class F>
    void ask(F&& change, Clock::time_point since) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!pending_) work_.since = since;
            change(work_);
            pending_ = true;
            cancel_ = true;  // the render under way is out of date
        }
        wake_.notify_one();
    }

    // The scene thread: evaluate, watch what was read, hand the scene over,
    // wait for a save. The FileWatcher is used by this thread only.
    void watch_loop(FileWatcher& watcher) {
        Clock::time_point since = Clock::now();
        for (;;) {
            std::vector<std::string> deps;
            EvalOptions eval = o_.eval;
            eval.on_dependency = [&deps](const std::string& p) { deps.push_back(p); };
            try {
                ProgressBar quiet(false);
                std::vector<Diagnostic> warnings;
                auto scene = std::make_shared<csg::Scene>(evaluate_and_lower(o_, eval, quiet, nullptr, &warnings));
                watcher.watch(deps);
                std::string text;
                for (const auto& w : warnings) text += format_diagnostic(w) + "\n";
                diagnostics(false, text);
                ask([&](Work& w) { w.scene = std::move(scene); }, since);
            } catch (...) {
                watcher.watch(deps);  // the fix will be saved to one of them
                int status_code = 0;
                const std::string text = describe_failure(std::current_exception(), &status_code);
                std::fprintf(stderr, "%s\n", text.c_str());
                diagnostics(true, text);
                status(have_image_ ? "the page keeps the last good image; waiting for a change" : "no image yet; waiting for a change");
            }
            watcher.wait(-1);
            since = Clock::now();
            watcher.settle(kQuietMs, kLongestMs);
            const std::string changed = watcher.take_changed();
            std::fprintf(stderr, "kerf view: %s changed\n", changed.c_str());
            status(changed + " changed; evaluating");
        }
    }

    // The render thread: owns the scene; renders it from the view asked for.
    void render_loop() {
        std::shared_ptr<csg::Scene> scene;
        csg::Camera scene_camera;  // the scene's own camera (the view's reset)
        for (;;) {
            Work w;
            {
                std::unique_lock<std::mutex> lock(mutex_);
                wake_.wait(lock, [&] { return pending_; });
                w = std::move(work_);
                work_ = Work{};
                pending_ = false;
                cancel_ = false;
            }
            if (w.scene) {
                // A saved camera statement (say, one pasted from "Copy
                // camera") takes over the view; otherwise the user's view
                // stays as the model changes under it.
                const bool new_camera = !scene || !same_camera(w.scene->camera, scene_camera);
                const csg::Camera view = scene ? scene->camera : w.scene->camera;
                scene_camera = w.scene->camera;
                scene = std::move(w.scene);
                if (!new_camera) scene->camera = view;
            }
            if (!scene) continue;
            if (w.reset) scene->camera = scene_camera;
            if (w.camera) scene->camera = *w.camera;
            render_stages(*scene, w.since);
        }
    }

    // The preview, then the full image, each published as soon as it is
    // done; a newer request cancels whichever is under way.
    void render_stages(const csg::Scene& scene, Clock::time_point since) {
        render::RenderOptions full = o_.render;
        full.srgb8 = true;
        full.cancel = &cancel_;
        render::RenderOptions quick = full;
        quick.width = std::max(1, full.width / kPreviewDivisor);
        quick.height = std::max(1, full.height / kPreviewDivisor);
        quick.preview = true;
        quick.adaptive = false;
        quick.spp = 1;
        // The path integrator's passes (1, 2, 4, ... paths per pixel) are
        // shown as they finish; the last one is the full image.
        if (full.integrator == render::Integrator::Path) {
            const auto started = Clock::now();
            full.on_pass = [&, started](const render::Image& image, int paths) {
                if (paths >= full.spp) return;
                render::RenderStats so_far;
                so_far.seconds = seconds(Clock::now() - started);
                const std::string stage = "paths " + std::to_string(paths) + "/" + std::to_string(full.spp);
                publish(scene.camera, image, so_far, stage.c_str(), full, seconds(Clock::now() - since));
            };
        }
        status("rendering");
        for (const auto& [stage, ro] : {std::pair{"preview", quick}, std::pair{"full", full}}) {
            render::RenderStats stats;
            render::Image image;
            try {
                image = render::render(scene, ro, &stats);
            } catch (const render::RenderCancelled&) {
                return;  // the next request is waiting
            } catch (...) {
                int status_code = 0;
                const std::string text = describe_failure(std::current_exception(), &status_code);
                std::fprintf(stderr, "%s\n", text.c_str());
                diagnostics(true, text);
                status("render failed");
                return;
            }
            publish(scene.camera, image, stats, stage, full, seconds(Clock::now() - since));
        }
        status("done");
    }

    void publish(const csg::Camera& camera, const render::Image& image, const render::RenderStats& stats,
                 const char* stage, const render::RenderOptions& full, double latency) {
        std::vector<unsigned char> png;
        const std::string failed = render::encode_png(png, image.srgb8.data(), image.width, image.height, image.channels, true);
        if (!failed.empty()) {
            diagnostics(true, "kerf: error: " + failed);
            return;
        }
        const std::uint64_t id = server_->put_image(std::move(png));
        have_image_ = true;
        const double rays = double(stats.rays());
        server_->publish(
            "image", "{\"id\":" + std::to_string(id) + ",\"url\":\"/image/" + std::to_string(id) + ".png\",\"stage\":\"" +
                         stage + "\",\"width\":" + std::to_string(image.width) + ",\"height\":" +
                         std::to_string(image.height) + ",\"full_width\":" + std::to_string(full.width) +
                         ",\"full_height\":" + std::to_string(full.height) + ",\"seconds\":" +
                         view::json_number(stats.seconds) + ",\"latency\":" + view::json_number(latency) +
                         ",\"rays\":" + view::json_number(rays) + ",\"mrays_per_s\":" +
                         view::json_number(stats.seconds > 0 ? rays / stats.seconds * 1e-6 : 0) +
                         ",\"camera\":" + view::camera_json(camera) + ",\"statement\":" +
                         view::json_string(view::camera_statement(camera)) + "}");
    }

    const Options& o_;
    std::unique_ptr<view::Server> server_;
    std::mutex mutex_;
    std::condition_variable wake_;
    Work work_;
    bool pending_ = false;
    std::atomic<bool> cancel_{false};
    std::atomic<bool> have_image_{false};
};

}  // namespace

int run_view(const Options& o) {
    // A page closed while its answer is written must not end kerf.
    std::signal(SIGPIPE, SIG_IGN);
    Session session(o);
    return session.run();
}

}  // namespace kerf::cli
