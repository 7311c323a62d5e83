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
#include "warm_chains.hpp"

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

detail::ShareChains share_of(const SweepSpec& spec, const SweepOptions& options) {
  return detail::share_chains(spec, options.first_point, options.offset, options.stride);
}

// The lowest invalid point the share delivers (the same whatever the number of threads: every
// point below the lowest failure found is checked).
std::optional<InvalidPoint> check_share(const SweepSpec& spec, const ProblemOfPoint& problem_of,
                                        const detail::ShareChains& share, int threads) {
  std::mutex mutex;
  std::size_t next = 0;                                         // chain m
  std::size_t worst = std::numeric_limits<std::size_t>::max();  // as m
  std::optional<InvalidPoint> lowest;
  // Claims of about 64 points.
  const std::size_t batch = std::max<std::size_t>(1, 64 / share.layout.length);
  on_threads(threads, [&] {
    for (;;) {
      std::size_t begin;
      {
        const std::lock_guard lock(mutex);
        if (next >= share.count || next > worst) return;
        begin = next;
        next = std::min(share.count, next + batch);
      }
      for (std::size_t m = begin; m < std::min(share.count, begin + batch); ++m) {
        for (std::size_t i = share.delivered_begin(m); i < share.solved(m).end; ++i) {
          try {
            checked_problem(problem_of, detail::point_of_valid_spec(spec, i));
          } catch (...) {
            const std::lock_guard lock(mutex);
            if (m < worst) {
              worst = m;
              lowest = InvalidPoint{i, std::current_exception()};
            }
            return;
          }
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

// The solve pass's shared state: claims of whole chains, the window of solved rows and the
// delivery.  Rows are numbered k = 0 .. share.points - 1 in point order.
class Window {
 public:
  Window(const SweepSpec& spec, const ProblemOfPoint& problem_of, const SweepOptions& options,
         const detail::ShareChains& share, int threads, SweepSummary& summary)
      : spec_(spec),
        problem_of_(problem_of),
        options_(options),
        share_(share),
        // A chain is claimed whole: the window holds the longest.
        slots_(std::max(std::max<std::size_t>(1, options.window_per_thread) * threads,
                        share.layout.length)),
        summary_(summary) {
    solver_ = options.solver;
    solver_.record_fields = false;
    solver_.puncture_top_stretch_start.reset();
    // The points before first_point in its chain are solved again for the chain's start only.
    rebuild_.puncture = true;
  }

  void work() {
    for (;;) {
      std::size_t m, k;
      {
        std::unique_lock lock(mutex_);
        room_.wait(lock, [&] {
          return finished() ||
                 next_claim_k_ + share_.delivered(next_chain_) <= next_delivery_ + slots_.size();
        });
        if (finished()) return;
        m = next_chain_++;
        k = next_claim_k_;
        next_claim_k_ += share_.delivered(m);
      }
      if (!solve_chain(m, k)) return;
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
  // No more claims: every chain claimed, an error, or a stop request.
  bool finished() const { return next_chain_ >= share_.count || error_ || stopped(); }

  // Chain m in order, its rows from number k on; each point's puncture search starts from the
  // last one found before it in the chain.  false after an error or a stop request.
  bool solve_chain(std::size_t m, std::size_t k) {
    SolverOptions solver = solver_;
    const PointRange points = share_.solved(m);
    const std::size_t delivered_from = share_.delivered_begin(m);
    for (std::size_t index = points.begin; index < points.end; ++index) {
      if (index > points.begin && stopped()) {
        // Threads waiting for room would not see the stop otherwise.
        { const std::lock_guard lock(mutex_); }
        room_.notify_all();
        return false;
      }
      std::optional<SweepRow> row;
      try {
        const SweepPoint point = detail::point_of_valid_spec(spec_, index);
        const bool delivered = index >= delivered_from;
        row = evaluate_point(
            checked_problem(problem_of_, point), delivered ? spec_.outputs : rebuild_, solver);
        row->point = point;
        if (row->puncture && row->puncture->part_two_top_stretch)
          solver.puncture_top_stretch_start = row->puncture->part_two_top_stretch;
        if (!delivered) continue;
      } catch (...) {
        fail(std::current_exception());
        return false;
      }
      deliver(std::move(*row), k++);
    }
    return true;
  }

  void fail(std::exception_ptr e) {
    const std::lock_guard lock(mutex_);
    if (!error_) error_ = std::move(e);
    room_.notify_all();
  }

  void deliver(SweepRow row, std::size_t k) {
    const std::lock_guard lock(mutex_);
    slots_[k % slots_.size()] = std::move(row);
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
    p.to_do = share_.points;
    p.failed = summary_.delivered - summary_.converged;
    p.elapsed_s = seconds_since(start_);
    options_.progress(p);
  }

  const SweepSpec& spec_;
  const ProblemOfPoint& problem_of_;
  const SweepOptions& options_;
  const detail::ShareChains& share_;
  SolverOptions solver_;                        // cold
  SweepOutputs rebuild_;                        // the puncture alone
  std::vector<std::optional<SweepRow>> slots_;  // row k in slot k % size, until delivered
  std::size_t next_chain_ = 0;                  // m of the next chain to solve
  std::size_t next_claim_k_ = 0;                // k of its first row
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
  return check_share(spec, problem_of, share_of(spec, options), thread_count(options.threads));
}

SweepSummary sweep(const SweepSpec& spec, const ProblemOfPoint& problem_of,
                   const SweepOptions& options) {
  check_arguments(spec, problem_of, options);
  const std::size_t count = point_count(spec);
  const detail::ShareChains share = share_of(spec, options);
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

  const std::size_t own = share.points;
  Window window(spec, problem_of, options, share, summary.threads, summary);
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
