#include "cgcm/io/CsvWriter.hpp"

#include <cstdio>
#include <stdexcept>

#include "cgcm/core/Error.hpp"

namespace cgcm::io {

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns)
    : path_(path), columns_(columns.size()), out_(path) {
  if (!out_) throw InputError("cannot write \"" + path + "\" (Output/Directory)");
  for (std::size_t i = 0; i < columns.size(); ++i) out_ << (i ? "," : "") << columns[i];
  out_ << "\n";
  out_.flush();
}

void CsvWriter::row(const std::vector<double>& values) {
  if (values.size() != columns_)
    throw std::logic_error("CSV row of " + std::to_string(values.size()) + " values for " +
                           std::to_string(columns_) + " columns in " + path_);
  char buf[32];
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.12g", values[i]);
    out_ << (i ? "," : "") << buf;
  }
  out_ << "\n";
  out_.flush();
}

}  // namespace cgcm::io
