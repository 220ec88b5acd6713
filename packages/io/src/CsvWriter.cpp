#include "cgcm/io/CsvWriter.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
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

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns, double lastKept)
    : path_(path), columns_(columns.size()) {
  std::string header;
  for (std::size_t i = 0; i < columns.size(); ++i) header += (i ? "," : "") + columns[i];
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line) || line != header)
    throw InputError("cannot continue \"" + path + "\": missing, or not written with the columns " + header);
  const std::string temporary = path + ".tmp";
  {
    std::ofstream kept(temporary);
    kept << header << "\n";
    while (std::getline(in, line)) {
      char* end = nullptr;
      const double first = std::strtod(line.c_str(), &end);
      if (end == line.c_str() || first > lastKept) break;
      kept << line << "\n";
    }
    if (!kept) throw InputError("cannot write \"" + temporary + "\" (Output/Directory)");
  }
  in.close();
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) throw InputError("cannot replace \"" + path + "\": " + ec.message());
  out_.open(path, std::ios::app);
  if (!out_) throw InputError("cannot write \"" + path + "\" (Output/Directory)");
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
