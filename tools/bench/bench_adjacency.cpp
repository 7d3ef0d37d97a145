// Adjacency building throughput: the project's builder against meshoptimizer on the same
// meshes. Both start from the raw, seamed TriMesh: meshopt_generateAdjacencyIndexBuffer dedups
// positions itself, so our timed work is the whole build_line_mesh (weld, clean, adjacency).
// The bare adjacency step on pre-welded indices is timed too, for reference.
#include <benchmark/benchmark.h>
#include <meshoptimizer.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "geometry/adjacency.h"
#include "geometry/line_mesh.h"
#include "geometry/primitives.h"
#include "geometry/weld.h"

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

// Console output plus, at the end, one line per mesh comparing the two full builders by wall
// time and by CPU time (the latter is steadier on a shared, loaded machine).
class RatioReporter : public benchmark::ConsoleReporter {
  public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs) {
            if (r.error_occurred || r.run_type != Run::RT_Iteration) continue;
            const std::string name = r.benchmark_name();
            const auto slash = name.find('/');
            times_[name.substr(0, slash)][name.substr(slash + 1)] = {r.GetAdjustedRealTime(),
                                                                     r.GetAdjustedCPUTime()};
        }
    }

    void Finalize() override {
        ConsoleReporter::Finalize();
        std::printf("\n%-16s %12s %12s %8s %12s %12s %8s\n", "mesh", "bz wall", "meshopt wall",
                    "speedup", "bz cpu", "meshopt cpu", "speedup");
        for (const auto& [mesh, t] : times_) {
            const auto ours = t.find("bz_line_mesh"), theirs = t.find("meshopt");
            if (ours == t.end() || theirs == t.end()) continue;
            const Times& o = ours->second;
            const Times& m = theirs->second;
            std::printf("%-16s %9.3f ms %9.3f ms %7.2fx %9.3f ms %9.3f ms %7.2fx\n", mesh.c_str(),
                        o.real, m.real, m.real / o.real, o.cpu, m.cpu, m.cpu / o.cpu);
        }
    }

  private:
    struct Times {
        double real = 0.0;
        double cpu = 0.0;
    };
    std::map<std::string, std::map<std::string, Times>> times_;
};

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
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}
