#pragma once
// A flat byte buffer for sending plain data from one rank to another: values,
// vectors of values and strings are appended in order and read back in the
// same order (both sides run the same build: no byte-order or padding
// translation).
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace cgcm::core {

class ByteWriter {
 public:
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "ByteWriter::put: plain data only");
    append(&value, sizeof(T));
  }
  template <class T>
  void put(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>, "ByteWriter::put: plain data only");
    put(std::uint64_t(values.size()));
    append(values.data(), values.size() * sizeof(T));
  }
  void put(const std::string& text) {
    put(std::uint64_t(text.size()));
    append(text.data(), text.size());
  }
  std::vector<char> take() { return std::move(bytes_); }

 private:
  void append(const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    bytes_.insert(bytes_.end(), p, p + size);
  }
  std::vector<char> bytes_;
};

/// Reads what a ByteWriter wrote (`bytes` must outlive the reader); reading past the end, or a count
/// beyond it, throws std::logic_error.
class ByteReader {
 public:
  explicit ByteReader(const std::vector<char>& bytes) : bytes_(bytes) {}
  ByteReader(std::vector<char>&&) = delete;
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>, "ByteReader::get: plain data only");
    T value;
    copy(&value, sizeof(T));
    return value;
  }
  template <class T>
  std::vector<T> getVector() {
    static_assert(std::is_trivially_copyable_v<T>, "ByteReader::getVector: plain data only");
    std::vector<T> values(count(sizeof(T)));
    copy(values.data(), values.size() * sizeof(T));
    return values;
  }
  std::string getString() {
    std::string text(count(1), '\0');
    copy(text.data(), text.size());
    return text;
  }
  /// A count the writer put before items of at least `itemSize` bytes each (checked against the rest).
  std::size_t getCount(std::size_t itemSize) { return count(itemSize); }
  bool atEnd() const { return position_ == bytes_.size(); }

 private:
  std::size_t count(std::size_t itemSize) {
    const auto n = get<std::uint64_t>();
    if (n > (bytes_.size() - position_) / itemSize) throw std::logic_error("ByteReader: a count beyond the buffer");
    return std::size_t(n);
  }
  void copy(void* to, std::size_t size) {
    if (size > bytes_.size() - position_) throw std::logic_error("ByteReader: read past the end of the buffer");
    if (size) std::memcpy(to, bytes_.data() + position_, size);
    position_ += size;
  }
  const std::vector<char>& bytes_;
  std::size_t position_ = 0;
};

}  // namespace cgcm::core
