#pragma once
// A CSV file with a header, flushed after every row so that a run that stops
// early leaves a valid file.
#include <fstream>
#include <string>
#include <vector>

namespace cgcm::io {

class CsvWriter {
 public:
  /// Opens `path` (truncating it) and writes the header. Throws InputError if it cannot.
  CsvWriter(const std::string& path, const std::vector<std::string>& columns);
  /// Continues the file `path` written with these columns: keeps its header and
  /// the rows whose first value is at most `lastKept` (a step number), drops the
  /// rest (rewriting the file through a temporary and a rename), then appends.
  /// Throws InputError if the file is missing or has another header.
  CsvWriter(const std::string& path, const std::vector<std::string>& columns, double lastKept);
  /// Writes one row; the number of values must match the header.
  void row(const std::vector<double>& values);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::size_t columns_;
  std::ofstream out_;
};

}  // namespace cgcm::io
