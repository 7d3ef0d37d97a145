// Adjacency building throughput: the project's builder against meshoptimizer on the same
// meshes. Both start from the raw, seamed TriMesh: meshopt_generateAdjacencyIndexBuffer dedups
// positions itself, so our timed work is the whole build_line_mesh (weld, clean, adjacency).
// The bare adjacency step on pre-welded indices is timed too, for reference.
#include <benchmark/benchmark.h>
#include <meshoptimizer.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/adjacency.h"
#include "geometry/line_mesh/line_mesh.h"
#include "geometry/line_mesh/weld.h"

namespace {

using bz::geo::TriMesh;

struct NamedMesh {
    std::string name;
    TriMesh mesh;
};

std::vector<NamedMesh> make_meshes() {
    std::vector<NamedMesh> meshes;
    // Grid tiles of 16 x 16 cells and the sphere's seam column and poles give seams to weld.
    for (const std::uint32_t n : {23u, 224u, 708u}) {
        meshes.push_back({"grid_" + std::to_string(2 * n * n), bz::geo::grid(n, n, 1.0f, 16)});
    }
    for (const auto& [rings, segments] : {std::pair{17u, 32u}, {225u, 224u}, {709u, 708u}}) {
        meshes.push_back({"sphere_" + std::to_string(2 * segments * (rings - 1)),
                          bz::geo::uv_sphere(1.0f, rings, segments)});
    }
    return meshes;
}

void set_rate(benchmark::State& state, const TriMesh& mesh) {
    state.counters["tris/s"] = benchmark::Counter(static_cast<double>(mesh.triangle_count()),
                                                  benchmark::Counter::kIsIterationInvariantRate);
    state.counters["tris"] = static_cast<double>(mesh.triangle_count());
}

void bench_line_mesh(benchmark::State& state, const TriMesh& mesh) {
    for (auto _ : state) {
        bz::geo::AdjacencyMesh out = bz::geo::build_line_mesh(mesh);
        benchmark::DoNotOptimize(out.adjacency.data());
    }
    set_rate(state, mesh);
}

void bench_meshopt(benchmark::State& state, const TriMesh& mesh) {
    std::vector<unsigned> dest(mesh.indices.size() * 2);
    for (auto _ : state) {
        meshopt_generateAdjacencyIndexBuffer(dest.data(), mesh.indices.data(), mesh.indices.size(),
                                             &mesh.positions[0].x, mesh.positions.size(),
                                             sizeof(glm::vec3));
        benchmark::DoNotOptimize(dest.data());
        benchmark::ClobberMemory();
    }
    set_rate(state, mesh);
}

void bench_adjacency_only(benchmark::State& state, const TriMesh& mesh) {
    const bz::geo::WeldedMesh welded = bz::geo::weld_positions(mesh);
    for (auto _ : state) {
        bz::geo::Adjacency out =
            bz::geo::build_adjacency(welded.triangles, welded.positions.size());
        benchmark::DoNotOptimize(out.adjacency.data());
    }
    set_rate(state, mesh);
}

// Whatever display Google Benchmark was asked for (--benchmark_format=console|json|csv; and
// --benchmark_out writes its own file as usual), plus, as an extra at the end, one line per
// mesh comparing the two full builders by wall time and by CPU time (the latter is steadier
// on a shared, loaded machine). The extra table goes to stdout after the console display, and
// to stderr after JSON or CSV, so that stdout stays a valid document.
class RatioReporter : public benchmark::BenchmarkReporter {
  public:
    RatioReporter(std::unique_ptr<benchmark::BenchmarkReporter> display, std::FILE* table_out)
        : display_(std::move(display)), table_out_(table_out) {}

    bool ReportContext(const Context& context) override { return display_->ReportContext(context); }

    void ReportRuns(const std::vector<Run>& runs) override {
        display_->ReportRuns(runs);
        for (const Run& r : runs) {
            if (r.error_occurred || r.run_type != Run::RT_Iteration) continue;
            const std::string name = r.benchmark_name();
            const auto slash = name.find('/');
            times_[name.substr(0, slash)][name.substr(slash + 1)] = {r.GetAdjustedRealTime(),
                                                                     r.GetAdjustedCPUTime()};
        }
    }

    void Finalize() override {
        display_->Finalize();
        std::fflush(stdout);
        std::fprintf(table_out_, "\n%-16s %12s %12s %8s %12s %12s %8s\n", "mesh", "bz wall",
                     "meshopt wall", "speedup", "bz cpu", "meshopt cpu", "speedup");
        for (const auto& [mesh, t] : times_) {
            const auto ours = t.find("bz_line_mesh"), theirs = t.find("meshopt");
            if (ours == t.end() || theirs == t.end()) continue;
            const Times& o = ours->second;
            const Times& m = theirs->second;
            std::fprintf(table_out_, "%-16s %9.3f ms %9.3f ms %7.2fx %9.3f ms %9.3f ms %7.2fx\n",
                         mesh.c_str(), o.real, m.real, m.real / o.real, o.cpu, m.cpu,
                         m.cpu / o.cpu);
        }
    }

  private:
    struct Times {
        double real = 0.0;
        double cpu = 0.0;
    };
    std::unique_ptr<benchmark::BenchmarkReporter> display_;
    std::FILE* table_out_;
    std::map<std::string, std::map<std::string, Times>> times_;
};

// The value of --benchmark_format=..., as Google Benchmark reads it (the last one wins);
// "console" when absent.
std::string display_format(int argc, char** argv) {
    constexpr std::string_view kFlag = "--benchmark_format=";
    std::string format = "console";
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a.substr(0, kFlag.size()) == kFlag) format = std::string(a.substr(kFlag.size()));
    }
    return format;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<NamedMesh> meshes = make_meshes();
    for (const NamedMesh& m : meshes) {
        const TriMesh& mesh = m.mesh;
        benchmark::RegisterBenchmark((m.name + "/bz_line_mesh").c_str(), [&mesh](
                                                                             benchmark::State& s) {
            bench_line_mesh(s, mesh);
        })->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark((m.name + "/meshopt").c_str(), [&mesh](benchmark::State& s) {
            bench_meshopt(s, mesh);
        })->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(
            (m.name + "/bz_adjacency_only").c_str(),
            [&mesh](benchmark::State& s) { bench_adjacency_only(s, mesh); })
            ->Unit(benchmark::kMillisecond);
    }
    const std::string format = display_format(argc, argv);
    benchmark::Initialize(&argc, argv);  // rejects a format other than these three
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    std::unique_ptr<benchmark::BenchmarkReporter> display;
    if (format == "json") {
        display = std::make_unique<benchmark::JSONReporter>();
    } else if (format == "csv") {
        // Deprecated upstream but still what --benchmark_format=csv gives; kept for parity.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
        display = std::make_unique<benchmark::CSVReporter>();
#pragma GCC diagnostic pop
    } else {
        display = std::make_unique<benchmark::ConsoleReporter>();
    }
    RatioReporter reporter(std::move(display), format == "console" ? stdout : stderr);
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}
