// The sweep engine: every point's problem checked first, then the points solved in parallel
// and delivered in point order through a bounded window (memory flat in the number of points).
#include <fmt/format.h>

#ifdef PUNCTURE_HAVE_OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>

#include "points.hpp"
#include "puncture/sweep.hpp"

namespace puncture {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

int thread_count(int asked) {
#ifdef PUNCTURE_HAVE_OPENMP
  return asked > 0 ? asked : omp_get_max_threads();
#else
  (void)asked;
  return 1;  // built without OpenMP: serial
#endif
}

// The problem of a point, validated.  Throws for an invalid one.
Problem checked_problem(const ProblemOfPoint& problem_of, const SweepPoint& point) {
  Problem problem = problem_of(point);
  if (auto errors = validation_errors(problem); !errors.empty())
    throw InvalidInput(std::move(errors),
                       fmt::format("invalid input at sweep point {}:", point.index));
  return problem;
}

// Runs `body(thread)` on `threads` threads (OpenMP), or once without OpenMP.
template <class Body>
void on_threads(int threads, Body&& body) {
#ifdef PUNCTURE_HAVE_OPENMP
#pragma omp parallel num_threads(threads)
  body();
#else
  (void)threads;
  body();
#endif
}

// This run's points first + offset + k stride, k = 0 .. own - 1.
struct Share {
  std::size_t first = 0, offset = 0, stride = 1, own = 0;
  std::size_t index(std::size_t k) const { return first + offset + k * stride; }
};

Share share_of(const SweepOptions& options, std::size_t count) {
  const std::size_t start = options.first_point + options.offset;
  const std::size_t own = start < count ? (count - start + options.stride - 1) / options.stride : 0;
  return {options.first_point, options.offset, options.stride, own};
}

// The lowest invalid point of the share (the same whatever the number of threads: every point
// below the lowest failure found is checked).
std::optional<InvalidPoint> check_share(const SweepSpec& spec, const ProblemOfPoint& problem_of,
                                        const Share& share, int threads) {
  std::mutex mutex;
  std::size_t next = 0;
  std::size_t worst = std::numeric_limits<std::size_t>::max();  // as k
  std::optional<InvalidPoint> lowest;
  constexpr std::size_t kChunk = 64;
  on_threads(threads, [&] {
    for (;;) {
      std::size_t begin;
      {
        const std::lock_guard lock(mutex);
        if (next >= share.own || next > worst) return;
        begin = next;
        next = std::min(share.own, next + kChunk);
      }
      for (std::size_t k = begin; k < std::min(share.own, begin + kChunk); ++k) {
        try {
          checked_problem(problem_of, detail::point_of_valid_spec(spec, share.index(k)));
        } catch (...) {
          const std::lock_guard lock(mutex);
          if (k < worst) {
            worst = k;
            lowest = InvalidPoint{share.index(k), std::current_exception()};
          }
          break;
        }
      }
    }
  });
  return lowest;
}

// The spec and the options, checked as every entry point needs them.
void check_arguments(const SweepSpec& spec, const ProblemOfPoint& problem_of,
                     const SweepOptions& options) {
  if (auto errors = validation_errors(spec); !errors.empty())
    throw InvalidInput(std::move(errors), "invalid sweep:");
  if (!problem_of) throw InvalidInput("problem_of", "problem_of: no function given");
  if (options.threads < 0)
    throw InvalidInput(
        "threads", fmt::format("threads: must be >= 0 (0: every core), got {}", options.threads));
  if (options.stride < 1 || options.offset >= options.stride)
    throw InvalidInput("stride",
                       fmt::format("stride: needs stride >= 1 and offset < stride, got {} and {}",
                                   options.stride,
                                   options.offset));
  const std::size_t count = point_count(spec);
  if (options.first_point > count)
    throw InvalidInput(
        "first_point",
        fmt::format("first_point: {} is beyond the sweep's {} points", options.first_point, count));
}

// The solve pass's shared state: claims, the window of solved rows and the delivery.
class Window {
 public:
  Window(const SweepSpec& spec, const ProblemOfPoint& problem_of, const SweepOptions& options,
         std::size_t count, int threads, SweepSummary& summary)
      : spec_(spec),
        problem_of_(problem_of),
        options_(options),
        count_(count),
        slots_(std::max<std::size_t>(1, options.window_per_thread) * threads),
        summary_(summary) {
    solver_ = options.solver;
    solver_.record_fields = false;
  }

  void work() {
    for (;;) {
      std::size_t index;
      {
        std::unique_lock lock(mutex_);
        room_.wait(lock,
                   [&] { return finished() || next_claim_ < next_delivery_ + slots_.size(); });
        if (finished()) return;
        index = point_index(next_claim_++);
      }
      std::optional<SweepRow> row;
      try {
        const SweepPoint point = detail::point_of_valid_spec(spec_, index);
        row = evaluate_point(checked_problem(problem_of_, point), spec_.outputs, solver_);
        row->point = point;
      } catch (...) {
        fail(std::current_exception());
        return;
      }
      deliver(std::move(*row));
    }
  }

  void rethrow_failure() const {
    if (error_) std::rethrow_exception(error_);
  }
  void report_progress() {
    const std::lock_guard lock(mutex_);
    call_progress();
  }
  Clock::time_point start() const { return start_; }

 private:
  bool stopped() const { return options_.stop && options_.stop->load(); }
  // No more claims: every point claimed, an error, or a stop request.
  bool finished() const { return next_claim_ >= count_ || error_ || stopped(); }

  void fail(std::exception_ptr e) {
    const std::lock_guard lock(mutex_);
    if (!error_) error_ = std::move(e);
    room_.notify_all();
  }

  void deliver(SweepRow row) {
    const std::lock_guard lock(mutex_);
    slots_[local_of(row.point.index) % slots_.size()] = std::move(row);
    try {
      // After an error nothing more is delivered: the rows delivered stay a prefix.
      for (auto* slot = &slots_[next_delivery_ % slots_.size()]; slot->has_value() && !error_;
           slot = &slots_[next_delivery_ % slots_.size()]) {
        count_row(**slot);
        if (options_.on_row) options_.on_row(**slot);
        slot->reset();
        ++next_delivery_;
      }
      if (options_.progress && seconds_since(last_progress_) >= options_.progress_every_s) {
        call_progress();
        last_progress_ = Clock::now();
      }
    } catch (...) {
      if (!error_) error_ = std::current_exception();
    }
    room_.notify_all();
  }

  void count_row(const SweepRow& row) {
    ++summary_.delivered;
    switch (row.failure_kind()) {
      case FailureKind::None:
        ++summary_.converged;
        break;
      case FailureKind::Physical:
        ++summary_.failed_physical;
        break;
      case FailureKind::Numerical:
        ++summary_.failed_numerical;
        break;
      case FailureKind::OutsideModel:
        ++summary_.failed_outside_model;
        break;
    }
  }

  void call_progress() {
    if (!options_.progress) return;
    SweepProgress p;
    p.done = summary_.delivered;
    p.to_do = count_;
    p.failed = summary_.delivered - summary_.converged;
    p.elapsed_s = seconds_since(start_);
    options_.progress(p);
  }

  const SweepSpec& spec_;
  const ProblemOfPoint& problem_of_;
  const SweepOptions& options_;
  SolverOptions solver_;
  // This process's points, k = 0 .. count_ - 1: first_point + offset + k stride.
  std::size_t point_index(std::size_t k) const {
    return options_.first_point + options_.offset + k * options_.stride;
  }
  std::size_t local_of(std::size_t index) const {
    return (index - options_.first_point - options_.offset) / options_.stride;
  }
  const std::size_t count_;
  std::vector<std::optional<SweepRow>> slots_;  // point k in slot k % size, until delivered
  std::size_t next_claim_ = 0;                  // k of the next point to solve
  std::size_t next_delivery_ = 0;               // k of the next row to deliver
  SweepSummary& summary_;
  std::exception_ptr error_;
  std::mutex mutex_;
  std::condition_variable room_;  // a slot freed, or no more claims
  const Clock::time_point start_ = Clock::now();
  Clock::time_point last_progress_ = Clock::now();
};

}  // namespace

std::optional<InvalidPoint> first_invalid_point(const SweepSpec& spec,
                                                const ProblemOfPoint& problem_of,
                                                const SweepOptions& options) {
  check_arguments(spec, problem_of, options);
  return check_share(
      spec, problem_of, share_of(options, point_count(spec)), thread_count(options.threads));
}

SweepSummary sweep(const SweepSpec& spec, const ProblemOfPoint& problem_of,
                   const SweepOptions& options) {
  check_arguments(spec, problem_of, options);
  const std::size_t count = point_count(spec);
  const Share share = share_of(options, count);
  SweepSummary summary;
  summary.total_points = count;
  summary.first_point = options.first_point;
  summary.threads = thread_count(options.threads);

  if (!options.points_checked) {
    const auto validation_start = Clock::now();
    if (const auto invalid = check_share(spec, problem_of, share, summary.threads))
      std::rethrow_exception(invalid->error);
    summary.validation_s = seconds_since(validation_start);
  }

  const std::size_t own = share.own;
  Window window(spec, problem_of, options, own, summary.threads, summary);
  on_threads(summary.threads, [&] { window.work(); });
  window.rethrow_failure();
  window.report_progress();  // the last word: every row delivered
  summary.solve_s = seconds_since(window.start());

  summary.own_points = own;
  const bool complete = summary.delivered == own;
  summary.status = complete ? Status::Converged : Status::Incomplete;
  if (!complete)
    summary.message =
        fmt::format("stopped after {} of this run's {} points: the rest were not solved",
                    summary.delivered,
                    own);
  return summary;
}

}  // namespace puncture
