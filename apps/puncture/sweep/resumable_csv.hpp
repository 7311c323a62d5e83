#pragma once
// The sweep's output file, never left truncated or corrupt under its own name:
//  - rows are appended, complete lines one write each, to OUT.part, next to a copy of the spec
//    it belongs to (OUT.part.spec);
//  - when every point is written, OUT.part becomes OUT (rename: atomic) and the copy goes;
//  - a run killed at any moment leaves OUT.part holding the header and the rows of points
//    0 .. k-1, at most its last line cut short; `--resume` checks that the spec is the same,
//    drops a cut line, and continues from point k.
#include <cstddef>
#include <string>

namespace puncture::cli {

class ResumableCsv {
 public:
  // A new sweep: OUT.part created with `header` (an existing OUT.part is refused: resume it
  // or remove it).  Throws InputError naming --output.
  static ResumableCsv start(const std::string& path, const std::string& header,
                            const std::string& spec_text);
  // The sweep OUT.part holds: throws InputError when there is none, when it belongs to another
  // spec or header, or when a row is not the next point's.
  static ResumableCsv resume(const std::string& path, const std::string& header,
                             const std::string& spec_text);

  ResumableCsv(ResumableCsv&& other) noexcept;
  ResumableCsv& operator=(ResumableCsv&&) = delete;
  ~ResumableCsv();

  std::size_t rows() const { return rows_; }  // complete rows in the file: the next point
  void append(const std::string& line);       // one complete line; throws SolveError on failure
  void finish();                              // OUT.part -> OUT
  // A new sweep that wrote no row (its spec refused before any solve): its files removed.
  void abandon_if_new_and_empty();

  std::string part_path() const { return path_ + ".part"; }

 private:
  ResumableCsv(std::string path, int fd, std::size_t rows, bool is_new);
  std::string path_;
  bool is_new_ = false;
  int fd_ = -1;
  std::size_t rows_ = 0;
};

}  // namespace puncture::cli
