#pragma once
// Sweeps: many problems solved through the same public API, for design maps and Monte Carlo.
//
//   SweepSpec    what: the parameters (by name), the design that places the points, the outputs
//   SweepOptions how: threads, where to resume, the row sink and the progress observer
//   SweepSummary what happened: points evaluated, failures by kind, rate
//
// The point list is deterministic: point i's inputs depend only on the spec and i (per-point
// seeds), never on the order in which points are solved.  Rows reach the sink in point order,
// one at a time, whatever the number of threads, so a sweep's output is identical bit for bit
// with 1 or N threads.  A point whose solve fails is a row with its Status, never dropped.
// A grid's points are solved in warm chains along its lines (SweepSpec::warm_start), each chain
// by one thread in order: a row depends on its chain alone, never on the threads, processes or
// resumes.
//
// The library does not know the parameters' names: the caller turns each point into a Problem
// (ProblemOfPoint); the CLI does it through its own flags, so every flag can be swept.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "puncture/options.hpp"
#include "puncture/outcome.hpp"
#include "puncture/problem.hpp"

namespace puncture {

// How the points are placed in the parameters' space.
enum class SweepDesign {
  Grid,            // every combination of the parameters' levels (the last varies fastest)
  LatinHypercube,  // `samples` points, exactly one in each of the `samples` equal-probability
                   // strata of every parameter
  Sobol,           // the first `samples` points of the Sobol sequence (Joe-Kuo direction
                   // numbers, the zero point skipped): quasi-Monte Carlo
  MonteCarlo,      // `samples` independent random points
};
std::string to_token(SweepDesign design);  // "grid", "latin-hypercube", "sobol", "monte-carlo"

enum class DistributionKind {
  Uniform,          // on [lower, upper]
  Normal,           // mean, sd
  LogNormal,        // mean, sd of the value itself (not of its logarithm); mean > 0
  TruncatedNormal,  // the normal(mean, sd) restricted to [lower, upper]
};
std::string to_token(
    DistributionKind kind);  // "uniform", "normal", "lognormal", "truncated-normal"

// A parameter's distribution, in the parameter's own unit.  LatinHypercube, Sobol and MonteCarlo
// draw a coordinate u in (0, 1) and map it through the quantile; uniform on the unit cube thus
// becomes this distribution (a stratum of u is a stratum of probability).
struct Distribution {
  DistributionKind kind = DistributionKind::Uniform;
  double lower = 0.0, upper = 1.0;  // Uniform, TruncatedNormal
  double mean = 0.0, sd = 0.0;      // Normal, LogNormal, TruncatedNormal
  double quantile(double u) const;  // u in (0, 1)
};

// `count` (>= 2) levels evenly spaced from lower to upper, both included, as text (the shortest
// decimal form of each double, which reads back exactly).
std::vector<std::string> evenly_spaced_levels(double lower, double upper, int count);

struct SweepParameter {
  std::string name;  // passed through to ProblemOfPoint (the CLI: the flag's long name)
  // Grid: the levels in order, as text (numbers, or words such as "sphere-tipped").
  std::vector<std::string> levels;
  // LatinHypercube, Sobol, MonteCarlo: the distribution sampled.
  Distribution distribution;
};

// What is computed at each point.
struct SweepOutputs {
  bool puncture = true;  // predict_puncture: force [N], depth [mm], stretch, where I1 peaks
  // The force [N] at each of these depths [mm] (solve_at_depth in the stage the problem's stick
  // rule gives there, as `puncture state --depth D --stage auto`).
  std::vector<double> force_at_depth_mm;
};

struct SweepSpec {
  SweepDesign design = SweepDesign::Grid;
  std::vector<SweepParameter> parameters;
  std::size_t samples = 0;  // points of LatinHypercube, Sobol, MonteCarlo (a Grid has its own)
  std::uint64_t seed = 0;   // LatinHypercube, MonteCarlo: the per-point seeds derive from it
  SweepOutputs outputs;
  // Grid: each point's puncture search starts from its neighbour's along a line of the last
  // parameter (SolverOptions::puncture_top_stretch_start), in chains of kWarmChainPoints; the
  // punctures then agree with cold solves to the shooting's tolerance, not bit for bit.  false:
  // every point cold, its row equal to a single solve's to the last digit.  The sampled designs
  // have no neighbours and are always cold.
  bool warm_start = true;
};

// The warm chains: a grid line of the last parameter cut into runs of at most kWarmChainPoints
// consecutive points (a line of L levels into ceil(L / kWarmChainPoints) runs), each solved in
// order, every point's puncture search starting from the one before.
inline constexpr std::size_t kWarmChainPoints = 16;

// The points [begin, end) solved as one chain with point `index` of a valid spec: its warm
// chain, or the point alone when the spec has none (warm_start off, a sampled design).
struct PointRange {
  std::size_t begin = 0, end = 0;
};
PointRange warm_chain_of(const SweepSpec& spec, std::size_t index);

// Which share (SweepOptions::offset) of `stride` shares of a run from `first_point` solves point
// `index` (>= first_point): the chains from first_point's on are dealt to the shares in turn.
std::size_t share_of_point(const SweepSpec& spec, std::size_t first_point, std::size_t stride,
                           std::size_t index);

// Every problem with the spec, each naming the parameter (parameters[j].name or the field);
// empty when valid.
std::vector<ValidationError> validation_errors(const SweepSpec& spec);

// The number of points: the product of the levels (Grid) or `samples`.
std::size_t point_count(const SweepSpec& spec);

struct SweepPoint {
  std::size_t index = 0;
  // Per parameter: the value as given to the problem (levels as written; sampled numbers in
  // their shortest exact decimal form) and as a number (NaN for a word).
  std::vector<std::string> texts;
  std::vector<double> values;
  std::uint64_t seed = 0;  // this point's own seed (from the spec's seed and the index)
};

// Point `index` (< point_count(spec)) of a valid spec.  Throws std::invalid_argument otherwise.
SweepPoint sweep_point(const SweepSpec& spec, std::size_t index);

// The problem at a point.  May throw (InvalidInput or the caller's own error) for a point that
// is not a valid problem; sweep() checks every point before it solves any.
using ProblemOfPoint = std::function<Problem(const SweepPoint&)>;

struct SweepPuncture : Outcome {  // of predict_puncture
  double force_n = 0.0;
  double depth_mm = 0.0;
  double part_three_stretch = 1.0;
  double max_first_invariant = 3.0;        // the failure measure at puncture
  double crack_reference_radius_mm = 0.0;  // where I1 peaks: reference radius ...
  double crack_radius_mm = 0.0;            // ... and current distance from the axis
  std::string crack_location;              // in words
  // Where a neighbouring point's puncture search can start (PuncturePrediction's); empty when
  // the puncture was not solved at the corner.
  std::optional<double> part_two_top_stretch;
};

struct SweepForceAtDepth : Outcome {  // of solve_at_depth
  double depth_mm = 0.0;
  double force_n = 0.0;
};

// One point's results.  status: Converged when every output was found, else the first failed
// output's status, the message naming the output.
struct SweepRow : Outcome {
  SweepPoint point;
  std::optional<SweepPuncture> puncture;    // when outputs.puncture
  std::vector<SweepForceAtDepth> at_depth;  // one per outputs.force_at_depth_mm
};

// Evaluates one problem (the work of one point; also what a benchmark times).
// With options.puncture_top_stretch_start (a warm start), a puncture that fails warm is solved
// again cold.
SweepRow evaluate_point(const Problem& problem, const SweepOutputs& outputs,
                        const SolverOptions& options = {});

struct SweepProgress {
  std::size_t done = 0;    // rows delivered in this run (after first_point)
  std::size_t to_do = 0;   // rows this run delivers in all
  std::size_t failed = 0;  // of those done, rows whose status is not Converged
  double elapsed_s = 0.0;  // since the solves started
};

struct SweepOptions {
  int threads = 0;              // 0: every core (OpenMP's default); 1: serial
  std::size_t first_point = 0;  // points before it are done already (resume); none delivered
                                // (those of its warm chain are solved again, for the chain)
  // This process solves the chains c0 + offset + k stride (k = 0, 1, ...), c0 the chain of
  // first_point (warm_chain_of; a chain is one point without warm starts): one share of a
  // sweep spread over processes (MPI rank `offset` of `stride`); rows in point order.
  std::size_t stride = 1;
  std::size_t offset = 0;
  // Rows solved ahead of the oldest undelivered one, per thread: bounds the memory held
  // whatever the number of points.
  std::size_t window_per_thread = 64;
  SolverOptions solver{};  // record_fields is switched off; the warm chains set the start
  // Receives every row in point order, one call at a time (from whichever thread drains the
  // window).  An exception thrown here stops the sweep and is rethrown by sweep().
  std::function<void(const SweepRow&)> on_row;
  // Called after rows are delivered (serialised with on_row), at most every `progress_every_s`.
  std::function<void(const SweepProgress&)> progress;
  double progress_every_s = 0.5;
  // When set and true, no further point is started; the rows solved are delivered and the
  // summary is Incomplete (e.g. set by a SIGINT handler).
  const std::atomic<bool>* stop = nullptr;
  // true: the caller found this run's points valid already (first_invalid_point with the same
  // spec, problem_of and options), and sweep() does not build each problem a second time.
  bool points_checked = false;
};

struct SweepSummary : Outcome {  // Converged when all own_points were delivered, else Incomplete
  std::size_t total_points = 0;
  std::size_t first_point = 0;
  std::size_t own_points = 0;  // this run's points: from first_point on, this process's share
  std::size_t delivered = 0;   // rows delivered in this run
  std::size_t converged = 0;
  std::size_t failed_physical = 0;
  std::size_t failed_numerical = 0;
  std::size_t failed_outside_model = 0;
  int threads = 1;
  double validation_s = 0.0;  // building and checking this run's points' problems
  double solve_s = 0.0;       // the solves and the sink
  double points_per_second() const;
  std::string brief_report() const;  // one line
  std::string full_report() const;
};

// The check sweep() makes before it solves anything: the lowest of this run's points (from
// options.first_point on, this process's share: offset, stride) whose problem is invalid, with
// the exception building it threw (problem_of's own, or InvalidInput); nullopt when all are
// valid.  Processes that each check their own share find the whole sweep's lowest invalid
// point by comparing the indices (the CLI's mpirun runs do).  Throws std::invalid_argument for
// an invalid spec or options, as sweep().
struct InvalidPoint {
  std::size_t index = 0;
  std::exception_ptr error;
};
std::optional<InvalidPoint> first_invalid_point(const SweepSpec& spec,
                                                const ProblemOfPoint& problem_of,
                                                const SweepOptions& options = {});

// Checks the spec and this run's points' problems (throws std::invalid_argument, or the
// problem_of's exception of the lowest invalid point; none when options.points_checked), then
// solves the points from options.first_point on (this process's share), in parallel,
// delivering every row in point order to options.on_row.
SweepSummary sweep(const SweepSpec& spec, const ProblemOfPoint& problem_of,
                   const SweepOptions& options = {});

}  // namespace puncture
