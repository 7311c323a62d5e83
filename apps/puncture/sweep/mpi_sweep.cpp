#include "mpi_sweep.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>

#include "cli_error.hpp"

#ifdef PUNCTURE_HAVE_MPI
#include <mpi.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "design_map.hpp"
#include "plot.hpp"
#include "problem_of_flags.hpp"
#include "resumable_csv.hpp"
#include "rows_csv.hpp"
#include "run_support.hpp"
#include "spec_file.hpp"
#include "statistics_report.hpp"
#endif

namespace puncture::cli {

bool launched_by_mpi() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(variable) != nullptr) return true;
  return false;
}

#ifndef PUNCTURE_HAVE_MPI

int run_sweep_mpi(const CLI::App&, const SweepFlags&, const OutputFlags&) {
  throw InputError(
      "sweep: started by mpirun, but this puncture was built without MPI (CMake "
      "-DPUNCTURE_MPI=ON with Debian's libopenmpi-dev); run it without mpirun (it uses every "
      "core with --threads)");
}

#else

namespace {

constexpr int kRowTag = 1;      // a row: one status byte ('c' converged, 'f' failed), the CSV line
constexpr int kEndTag = 2;      // a rank's last message: its counts (EndCounts)
constexpr int kInvalidTag = 3;  // why the sweep's lowest invalid point is invalid (its owner's)
using EndCounts = std::array<std::uint64_t, 5>;  // delivered, converged, physical, numerical,
                                                 // outside the model
constexpr std::uint64_t kRefused = std::numeric_limits<std::uint64_t>::max();

// Waits without spinning: Open MPI's blocking calls poll at full speed, and a rank done
// before the others would burn its core (and, on a shared or oversubscribed machine, the time
// of the ranks still solving) until they end.  A millisecond's delay is nothing to a sweep.
constexpr auto kIdlePoll = std::chrono::milliseconds(1);

void barrier_idly() {
  MPI_Request request;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(kIdlePoll);
  }
}

class MpiSession {
 public:
  MpiSession() {
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided_);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  // A rank done first waits for the others idly (MPI_Finalize would spin).
  ~MpiSession() {
    barrier_idly();
    MPI_Finalize();
  }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Rows are sent from whichever thread delivers them (one at a time): SERIALIZED needed, else
  // the rank solves on its main thread alone.
  bool threads_may_send() const { return provided_ >= MPI_THREAD_SERIALIZED; }

 private:
  int provided_ = 0, rank_ = 0, size_ = 1;
};

// Rank 0 refused the output file or the --plot target (`error` on rank 0: why), or reports
// an invalid point (no `error`); every rank ends with it.
struct RefusedByRankZero {
  std::exception_ptr error;
};

EndCounts counts_of(const SweepSummary& s) {
  return {s.delivered, s.converged, s.failed_physical, s.failed_numerical, s.failed_outside_model};
}

// Rank 0's writer: its own rows and the other ranks' in point order; point g belongs to rank
// share_of_point(spec, first, P, g) (its warm chain's, dealt in turn), and each rank's rows
// arrive in its own order (MPI keeps the order of one sender's messages).
class OrderedWriter {
 public:
  OrderedWriter(ResumableCsv& csv, const SweepSpec& spec, int ranks, std::size_t first,
                std::size_t total, std::function<void(const SweepProgress&)> progress,
                double progress_every_s)
      : csv_(csv),
        spec_(spec),
        ranks_(static_cast<std::size_t>(ranks)),
        first_(first),
        total_(total),
        ended_(ranks_, false),
        queued_(ranks_),
        progress_(std::move(progress)),
        progress_every_s_(progress_every_s) {}

  void own(const SweepRow& row) {
    own_.push_back({row.ok() ? 'c' : 'f', sweep_csv_line(row)});
    pump(false);
  }

  // Writes every row that is there (block: waits for the others' rows until each rank ended).
  void pump(bool block) {
    for (;;) {
      receive(kMaxQueued);
      const std::size_t g = first_ + written_;
      if (g >= total_) return;
      const std::size_t owner = share_of_point(spec_, first_, ranks_, g);
      auto& rows = owner == 0 ? own_ : queued_[owner];
      if (!rows.empty()) {
        write(rows.front().first, rows.front().second);
        rows.pop_front();
        continue;
      }
      // Rank 0's next row not solved yet (or it stopped); another rank's not there yet, or that
      // rank stopped before this point: the file ends here.
      if (owner == 0 || ended_[owner] || !block) return;
      std::this_thread::sleep_for(kIdlePoll);
    }
  }

  // The other ranks' ends not yet received (they follow their last row).  Rows still queued
  // lie beyond a gap: the file stops before them; a resume solves them again.
  void collect_ends() {
    while (std::find(ended_.begin() + 1, ended_.end(), false) != ended_.end()) {
      receive(std::numeric_limits<std::size_t>::max());
      for (auto& rows : queued_) rows.clear();
      std::this_thread::sleep_for(kIdlePoll);
    }
  }

  std::size_t written() const { return written_; }
  const EndCounts& others() const { return others_; }
  void report() {
    if (progress_) progress_(progress_now());
  }
  double elapsed_s() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  void write(char status, const std::string& line) {
    csv_.append(line);
    ++written_;
    failed_ += status != 'c';
    if (progress_ &&
        std::chrono::duration<double>(Clock::now() - last_).count() >= progress_every_s_) {
      progress_(progress_now());
      last_ = Clock::now();
    }
  }
  SweepProgress progress_now() const {
    return {written_,
            total_ - first_,
            failed_,
            std::chrono::duration<double>(Clock::now() - start_).count()};
  }
  void add(const EndCounts& c) {
    for (std::size_t k = 0; k < c.size(); ++k) others_[k] += c[k];
  }

  // Takes every message there from the other ranks, in whatever order they come, up to
  // `most` rows queued per rank: a rank's MPI_Send then finds its rows taken and does not spin
  // waiting for rank 0 to reach them (each rank's rows arrive in its own order).
  void receive(std::size_t most) {
    for (std::size_t q = 1; q < ranks_; ++q) {
      const int source = static_cast<int>(q);
      while (!ended_[q] && queued_[q].size() < most) {
        int there = 0;
        MPI_Status status;
        MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &there, &status);
        if (!there) break;
        if (status.MPI_TAG == kEndTag) {
          EndCounts counts;
          MPI_Recv(counts.data(), 5, MPI_UINT64_T, source, kEndTag, MPI_COMM_WORLD, &status);
          ended_[q] = true;
          add(counts);
          break;
        }
        int bytes = 0;
        MPI_Get_count(&status, MPI_CHAR, &bytes);
        std::string message(static_cast<std::size_t>(bytes), '\0');
        MPI_Recv(message.data(), bytes, MPI_CHAR, source, kRowTag, MPI_COMM_WORLD, &status);
        queued_[q].emplace_back(message[0], message.substr(1));
      }
    }
  }

  using Clock = std::chrono::steady_clock;
  ResumableCsv& csv_;
  const SweepSpec& spec_;
  std::size_t ranks_, first_, total_;
  std::vector<bool> ended_;
  // Rows solved, not yet written: rank 0's own, and those received from rank q (queued_[q]).
  static constexpr std::size_t kMaxQueued = 4096;  // per rank: ~1 MB of rows
  std::deque<std::pair<char, std::string> > own_;
  std::vector<std::deque<std::pair<char, std::string> > > queued_;
  std::size_t written_ = 0, failed_ = 0;
  EndCounts others_{};
  std::function<void(const SweepProgress&)> progress_;
  double progress_every_s_;
  Clock::time_point start_ = Clock::now(), last_ = Clock::now();
};

// This rank's warm chains from `first`'s on: rank, rank + P, ... (each point its own chain
// without warm starts).
SweepOptions share_options(const MpiSession& mpi, const SweepFlags& f, std::size_t first) {
  SweepOptions options;
  options.threads = mpi.threads_may_send() ? f.threads : 1;
  options.first_point = first;
  options.stride = static_cast<std::size_t>(mpi.size());
  options.offset = static_cast<std::size_t>(mpi.rank());
  options.stop = &interrupt_flag();
  return options;
}

std::string what_of(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "an unknown error";
  }
}

// Each rank checks its own points only (a serial run's check, split); the sweep's lowest
// invalid point is then reported by rank 0 with its owner's message, as the serial run
// reports it: InputError on rank 0, RefusedByRankZero on the others.
void check_points_together(const MpiSession& mpi, const SweepSpec& spec,
                           const ProblemOfPoint& problem_of, const SweepOptions& options) {
  constexpr std::uint64_t kNone = std::numeric_limits<std::uint64_t>::max();
  const auto invalid = first_invalid_point(spec, problem_of, options);
  const std::uint64_t mine = invalid ? invalid->index : kNone;
  std::uint64_t lowest = kNone;
  MPI_Allreduce(&mine, &lowest, 1, MPI_UINT64_T, MPI_MIN, MPI_COMM_WORLD);
  if (lowest == kNone) return;
  const int owner =
      static_cast<int>(share_of_point(spec, options.first_point, options.stride, lowest));
  std::string why;
  if (owner == mpi.rank()) why = what_of(invalid->error);
  if (owner != 0 && owner == mpi.rank())
    MPI_Send(why.data(), static_cast<int>(why.size()), MPI_CHAR, 0, kInvalidTag, MPI_COMM_WORLD);
  if (mpi.rank() != 0) throw RefusedByRankZero{};
  if (owner != 0) {
    MPI_Status status;
    MPI_Probe(owner, kInvalidTag, MPI_COMM_WORLD, &status);
    int bytes = 0;
    MPI_Get_count(&status, MPI_CHAR, &bytes);
    why.assign(static_cast<std::size_t>(bytes), '\0');
    MPI_Recv(why.data(), bytes, MPI_CHAR, owner, kInvalidTag, MPI_COMM_WORLD, &status);
  }
  throw InputError(why);
}

// A rank other than 0: solves its share (checked), sends every row, then its counts.
int run_share(const SweepFile& file, const ProblemOfPoint& problem_of, SweepOptions options) {
  options.on_row = [](const SweepRow& row) {
    std::string message(1, row.ok() ? 'c' : 'f');
    message += sweep_csv_line(row);
    MPI_Send(
        message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, kRowTag, MPI_COMM_WORLD);
  };
  SweepSummary summary;
  const StopOnSignals signals;
  try {
    summary = sweep(file.spec, problem_of, options);
  } catch (...) {
    // Rank 0's file stops before this rank's first missing row.
    const EndCounts none{};
    MPI_Send(none.data(), 5, MPI_UINT64_T, 0, kEndTag, MPI_COMM_WORLD);
    throw;
  }
  const EndCounts counts = counts_of(summary);
  MPI_Send(counts.data(), 5, MPI_UINT64_T, 0, kEndTag, MPI_COMM_WORLD);
  return kExitOk;
}

int run_rank(const MpiSession& mpi, const CLI::App& app, const SweepFlags& f,
             const OutputFlags& output) {
  const bool root = mpi.rank() == 0;
  SweepFile file;
  // Every rank reads the same spec and meets the same errors (InputError: see run_sweep_mpi).
  check_sweep_flags(app, output);
  file = read_sweep_file(f.spec_path);
  const std::size_t total = point_count(file.spec);
  std::optional<ResumableCsv> csv;
  std::optional<std::string> plot;
  std::uint64_t first = kRefused;
  std::exception_ptr refused;
  if (root) {
    try {
      plot = design_map_target(app);  // rank 0 alone draws it
      const std::string header = sweep_csv_header(file.spec);
      const std::string spec_text = file_text(f.spec_path);
      csv.emplace(f.resume ? ResumableCsv::resume(output.path, header, spec_text)
                           : ResumableCsv::start(output.path, header, spec_text));
      if (csv->rows() > total)
        throw InputError(fmt::format("--resume: '{}' has {} rows, the sweep {} points",
                                     csv->part_path(),
                                     csv->rows(),
                                     total));
      first = csv->rows();
    } catch (...) {
      refused = std::current_exception();
    }
  }
  MPI_Bcast(&first, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  if (refused) throw RefusedByRankZero{refused};
  if (first == kRefused) throw RefusedByRankZero{};
  SweepOptions options = share_options(mpi, f, first);
  const ProblemOfPoint problem_of = problem_of_flags(file.spec, file.fixed);
  try {
    check_points_together(mpi, file.spec, problem_of, options);
  } catch (const InputError&) {
    if (csv) csv->abandon_if_new_and_empty();  // rank 0's
    throw;
  }
  options.points_checked = true;
  if (!root) return run_share(file, problem_of, options);

  const bool terminal = isatty(STDERR_FILENO) == 1;
  OrderedWriter writer(*csv,
                       file.spec,
                       mpi.size(),
                       first,
                       total,
                       f.quiet ? nullptr : progress_line(terminal, first, total),
                       terminal ? 0.5 : 10.0);
  options.on_row = [&writer](const SweepRow& row) { writer.own(row); };
  SweepSummary summary;
  {
    const StopOnSignals signals;
    try {
      summary = sweep(file.spec, problem_of, options);
    } catch (const InvalidInput& e) {
      writer.collect_ends();
      csv->abandon_if_new_and_empty();
      throw InputError(e.what());
    } catch (const InputError&) {
      writer.collect_ends();
      csv->abandon_if_new_and_empty();
      throw;
    }
    writer.pump(true);
    writer.collect_ends();
  }
  const EndCounts& others = writer.others();
  summary.delivered += others[0];
  summary.converged += others[1];
  summary.failed_physical += others[2];
  summary.failed_numerical += others[3];
  summary.failed_outside_model += others[4];
  const bool complete = first + writer.written() == total;
  if (!f.quiet) {
    writer.report();
    fmt::print(stderr,
               "{}sweep {} on {} MPI processes: {} of {} points ({} resumed), {} converged, {} "
               "failed; {:.3g} s ({:.3g} points/s)\n",
               terminal ? "\r\033[K" : "",
               complete ? "complete" : "incomplete",
               mpi.size(),
               first + writer.written(),
               total,
               first,
               summary.converged,
               summary.delivered - summary.converged,
               writer.elapsed_s(),
               static_cast<double>(writer.written()) / writer.elapsed_s());
  }
  if (complete) {
    csv->finish();
    if (f.statistics) fmt::print("{}", sweep_statistics_report(output.path, file.spec));
    if (plot) draw_design_map(output.path, file.spec, *plot);
    return kExitOk;
  }
  fmt::print(stderr,
             "puncture: sweep interrupted: {} of {} points in '{}'; continue with --resume\n",
             csv->rows(),
             total,
             csv->part_path());
  return kExitSolverFailure;
}

}  // namespace

int run_sweep_mpi(const CLI::App& app, const SweepFlags& f, const OutputFlags& output) {
  const MpiSession mpi;
  // Invalid input: an invalid spec is met by every rank, an invalid point by the rank owning
  // it, which tells rank 0; rank 0 says why, then all end together (a rank ending first would
  // have mpirun stop rank 0 before it speaks).
  const auto together = [&mpi](const char* what) {
    if (mpi.rank() == 0 && what) fmt::print(stderr, "puncture: error: {}\n", what);
    MPI_Barrier(MPI_COMM_WORLD);
    return kExitBadInput;
  };
  try {
    return run_rank(mpi, app, f, output);
  } catch (const InputError& e) {
    return together(e.what());
  } catch (const InvalidInput& e) {
    return together(e.what());
  } catch (const RefusedByRankZero& refused) {
    if (!refused.error) return together(nullptr);
    try {
      std::rethrow_exception(refused.error);
    } catch (const PlotError& e) {
      fmt::print(stderr, "puncture: plot failed: {}\n", e.what());
      MPI_Barrier(MPI_COMM_WORLD);
      return kExitPlotFailure;
    } catch (const std::exception& e) {
      return together(e.what());
    }
  } catch (const PlotError& e) {  // the map of a finished sweep: every rank is done
    fmt::print(stderr, "puncture: plot failed: {}\n", e.what());
    return kExitPlotFailure;
  } catch (const std::exception& e) {  // e.g. FILE cannot be written: the job cannot go on
    fmt::print(stderr, "puncture: sweep failed on MPI rank {}: {}\n", mpi.rank(), e.what());
    MPI_Abort(MPI_COMM_WORLD, kExitSolverFailure);
    return kExitSolverFailure;
  }
}

#endif

}  // namespace puncture::cli
