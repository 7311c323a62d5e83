#include "resumable_csv.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_error.hpp"

namespace puncture::cli {

namespace {

std::string spec_copy_path(const std::string& path) { return path + ".part.spec"; }

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_all(int fd, const std::string& text, const std::string& path) {
  const char* data = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw SolveError(fmt::format("--output: cannot write '{}': {}", path, std::strerror(errno)));
    data += n;
    left -= static_cast<std::size_t>(n);
  }
}

int open_for_append(const std::string& path, int extra_flags) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC | extra_flags, 0644);
  if (fd < 0)
    throw InputError(
        fmt::format("--output: cannot open '{}' for writing: {}", path, std::strerror(errno)));
  return fd;
}

}  // namespace

ResumableCsv::ResumableCsv(std::string path, int fd, std::size_t rows, bool is_new)
    : path_(std::move(path)), is_new_(is_new), fd_(fd), rows_(rows) {}

ResumableCsv::ResumableCsv(ResumableCsv&& other) noexcept
    : path_(std::move(other.path_)), is_new_(other.is_new_), fd_(other.fd_), rows_(other.rows_) {
  other.fd_ = -1;
}

ResumableCsv::~ResumableCsv() {
  if (fd_ >= 0) ::close(fd_);
}

ResumableCsv ResumableCsv::start(const std::string& path, const std::string& header,
                                 const std::string& spec_text) {
  const std::string part = path + ".part";
  if (std::filesystem::exists(part))
    throw InputError(fmt::format(
        "--output: '{}' holds an unfinished sweep: continue it with --resume, or remove it", part));
  {
    std::ofstream copy(spec_copy_path(path), std::ios::binary | std::ios::trunc);
    copy << spec_text;
    if (!copy) throw InputError(fmt::format("--output: cannot write '{}'", spec_copy_path(path)));
  }
  const int fd = open_for_append(part, O_CREAT | O_EXCL);
  ResumableCsv csv(path, fd, 0, true);
  write_all(fd, header, part);
  return csv;
}

ResumableCsv ResumableCsv::resume(const std::string& path, const std::string& header,
                                  const std::string& spec_text) {
  const std::string part = path + ".part";
  if (!std::filesystem::exists(part))
    throw InputError(fmt::format(
        "--resume: no unfinished sweep '{}'{}",
        part,
        std::filesystem::exists(path) ? fmt::format(" ('{}' is complete)", path) : std::string()));
  if (!std::filesystem::exists(spec_copy_path(path)) || contents(spec_copy_path(path)) != spec_text)
    throw InputError(fmt::format(
        "--resume: '{}' was started from another spec (its copy '{}' differs from this one)",
        part,
        spec_copy_path(path)));
  const std::string text = contents(part);
  if (text.compare(0, header.size(), header) != 0)
    throw InputError(fmt::format("--resume: '{}' does not start with this sweep's header", part));
  // Complete lines only: each the next point's.
  std::size_t rows = 0, end = header.size();
  for (std::size_t next; (next = text.find('\n', end)) != std::string::npos; end = next + 1) {
    const std::string expected = std::to_string(rows) + ",";
    if (text.compare(end, expected.size(), expected) != 0)
      throw InputError(
          fmt::format("--resume: '{}' row {} is not point {}: the file is not this sweep's",
                      part,
                      rows + 1,
                      rows));
    ++rows;
  }
  std::error_code ec;
  std::filesystem::resize_file(part, end, ec);  // drops a line cut short by the kill
  if (ec) throw InputError(fmt::format("--resume: cannot truncate '{}': {}", part, ec.message()));
  return ResumableCsv(path, open_for_append(part, 0), rows, false);
}

void ResumableCsv::append(const std::string& line) {
  write_all(fd_, line, part_path());
  ++rows_;
}

void ResumableCsv::finish() {
  if (::fsync(fd_) != 0 || ::close(fd_) != 0) {
    fd_ = -1;
    throw SolveError(
        fmt::format("--output: cannot write '{}': {}", part_path(), std::strerror(errno)));
  }
  fd_ = -1;
  std::error_code ec;
  std::filesystem::rename(part_path(), path_, ec);
  if (ec)
    throw SolveError(
        fmt::format("--output: cannot rename '{}' to '{}': {}", part_path(), path_, ec.message()));
  std::filesystem::remove(spec_copy_path(path_), ec);
}

void ResumableCsv::abandon_if_new_and_empty() {
  if (!is_new_ || rows_ > 0 || fd_ < 0) return;
  ::close(fd_);
  fd_ = -1;
  std::error_code ec;
  std::filesystem::remove(part_path(), ec);
  std::filesystem::remove(spec_copy_path(path_), ec);
}

}  // namespace puncture::cli
