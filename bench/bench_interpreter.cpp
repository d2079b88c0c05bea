// Interpreter throughput (plain main, no Google Benchmark needed):
//  (a) evaluate a loop nest that instantiates 1,000,000 translated spheres;
//  (b) parse a generated 10 MB script;
//  (c) evaluate 100,000 top-level bindings, each using the one before.
// Each case runs in a forked child so its peak RSS is its own (wait4's
// rusage), and reports the median wall time of 5 runs.
// Targets: (a) < 2 s on one core and < 1 GB; (b) < 1 s; (c) < 0.5 s (it
// was quadratic: 30,000 took 9 s).
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "grammar/parser.hpp"
#include "interpreter/interpreter.hpp"

namespace {

constexpr int kRuns = 5;

double cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

struct Timing {
    double wall_ms, cpu_ms;  // medians; CPU time is what counts on a busy machine
};

Timing median_ms(const std::function<void()>& run) {
    std::vector<double> wall, cpu;
    for (int i = 0; i < kRuns; ++i) {
        auto t0 = std::chrono::steady_clock::now();
        double c0 = cpu_ms();
        run();
        cpu.push_back(cpu_ms() - c0);
        wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    return {wall[kRuns / 2], cpu[kRuns / 2]};
}

std::shared_ptr<const kerf::SourceFile> make_file(std::string name, std::string text) {
    auto f = std::make_shared<kerf::SourceFile>();
    f->path = std::move(name);
    f->text = std::move(text);
    return f;
}

void bench_million_primitives() {
    auto file = make_file("million.sdl",
                          "for (i = [0:999]) for (j = [0:999]) translate([i, j, 0]) sphere(0.4);\n");
    kerf::EvalOptions options;
    options.limits.primitives = 2'000'000;
    std::size_t nodes = 0;
    Timing t = median_ms([&] {
        kerf::EvalResult r = kerf::evaluate_source(file, options);
        nodes = r.graph.nodes.size();
    });
    std::printf("eval 1M primitives: median %.1f ms wall, %.1f ms CPU over %d runs (%zu scene-graph nodes)\n",
                t.wall_ms, t.cpu_ms, kRuns, nodes);
}

// A script of ordinary statements (definitions, expressions, comprehensions,
// nested blocks, comments, strings) repeated with distinct names to 10 MB.
std::string generated_script(std::size_t bytes) {
    std::string s;
    s.reserve(bytes + 1024);
    char buf[1024];
    for (int k = 0; s.size() < bytes; ++k) {
        std::snprintf(buf, sizeof buf,
                      "// block %d: a module, a function and some geometry\n"
                      "module part_%d(a = %d, b = 2.5, center = true) {\n"
                      "    translate([a, b * 2, -3.5e-1]) rotate([0, 90, a * 15])\n"
                      "        difference() { cube([a + 1, b, 3], center = center); sphere(r = b / 2); }\n"
                      "}\n"
                      "function f_%d(x, y = [1, 2, 3]) = x < 0 ? -x : norm(y) + x * x / (1 + abs(x)) ^ 2;\n"
                      "v_%d = [for (i = [0 : 2 : 20]) if (i %% 3 != 0) let (j = i * i) [i, j, \"s%d\"]];\n"
                      "if (v_%d[0].x >= 1 && !false) part_%d(b = %d.25); else { sphere(1); }\n",
                      k, k, k % 97, k, k, k, k, k, k % 13);
        s += buf;
    }
    return s;
}

void bench_parse_10mb() {
    auto file = make_file("generated.sdl", generated_script(10u << 20));
    std::size_t stmts = 0;
    Timing t = median_ms([&] { stmts = kerf::parse_program(file).stmts.size(); });
    std::printf("parse %.1f MB: median %.1f ms wall, %.1f ms CPU over %d runs (%zu top-level statements)\n",
                static_cast<double>(file->text.size()) / (1 << 20), t.wall_ms, t.cpu_ms, kRuns, stmts);
}

void bench_100k_bindings() {
    std::string text = "v0 = 0;\n";
    for (int i = 1; i < 100'000; ++i) text += "v" + std::to_string(i) + " = v" + std::to_string(i - 1) + " + 1;\n";
    text += "echo(v99999);\n";
    auto file = make_file("bindings.sdl", std::move(text));
    kerf::EvalOptions options;
    options.echo = [](const std::string&) {};
    Timing t = median_ms([&] { kerf::evaluate_source(file, options); });
    std::printf("eval 100k bindings: median %.1f ms wall, %.1f ms CPU over %d runs\n", t.wall_ms, t.cpu_ms, kRuns);
}

// Runs `body` in a child process and prints the child's peak RSS.
int in_child(const char* label, void (*body)()) {
    std::fflush(stdout);
    pid_t pid = fork();
    if (pid < 0) return 1;
    if (pid == 0) {
        try {
            body();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s: %s\n", label, e.what());
            std::fflush(stdout);
            _exit(1);
        }
        std::fflush(stdout);
        _exit(0);
    }
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    std::printf("%s: peak RSS %.1f MB%s\n", label, usage.ru_maxrss / 1024.0,
                WIFEXITED(status) && WEXITSTATUS(status) == 0 ? "" : " (FAILED)");
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

}  // namespace

int main() {
    int failures = 0;
    failures += in_child("eval 1M primitives", bench_million_primitives) != 0;
    failures += in_child("parse 10 MB", bench_parse_10mb) != 0;
    failures += in_child("eval 100k bindings", bench_100k_bindings) != 0;
    return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
