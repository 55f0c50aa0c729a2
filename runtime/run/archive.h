// A binary archive that one listing of fields both writes and reads: a type lists its fields
// once, in `Serialize(Archive&)`, and the same code saves it into a checkpoint and restores it,
// so the two directions cannot drift apart. Reading checks every vector against the size the
// restored object already has (sized by MakeData or Reset): a checkpoint of another model fails
// instead of overrunning.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

namespace sled::runtime {

class Archive {
 public:
  static Archive ForWriting() { return Archive(false, {}); }
  static Archive ForReading(std::string bytes) { return Archive(true, std::move(bytes)); }

  bool reading() const { return reading_; }
  // False once a read ran past the end or met a size that does not fit.
  bool ok() const { return ok_; }
  const std::string& bytes() const { return bytes_; }
  bool at_end() const { return offset_ == bytes_.size(); }
  // Marks the archive failed (a reader that found something that does not fit).
  void Fail() { ok_ = false; }

  // Plain values and structs of plain values.
  template <class T>
  requires(std::is_trivially_copyable_v<T> &&
           !std::is_base_of_v<Eigen::EigenBase<T>, T>) void Field(T& value) {
    Raw(&value, sizeof(T));
  }
  // Fixed-size Eigen matrices (Vec3, Mat3, Vec6, ...).
  template <class Scalar, int Rows, int Cols, int Options, int MaxRows, int MaxCols>
  requires(Rows > 0 &&
           Cols >
               0) void Field(Eigen::Matrix<Scalar, Rows, Cols, Options, MaxRows, MaxCols>& value) {
    Raw(value.data(), sizeof(Scalar) * Rows * Cols);
  }
  // A dynamic Eigen matrix or vector: its shape, then its values.
  template <class Scalar, int Rows, int Cols, int Options, int MaxRows, int MaxCols>
  requires(Rows == Eigen::Dynamic || Cols == Eigen::Dynamic) void Field(
      Eigen::Matrix<Scalar, Rows, Cols, Options, MaxRows, MaxCols>& value) {
    std::int64_t rows = value.rows(), cols = value.cols();
    Field(rows);
    Field(cols);
    if (reading_ && (rows != value.rows() || cols != value.cols())) ok_ = false;
    if (ok_) Raw(value.data(), sizeof(Scalar) * static_cast<std::size_t>(value.size()));
  }
  // A vector whose size the reader already has: the size is checked, then the elements.
  template <class T>
  void Field(std::vector<T>& values) {
    std::int64_t size = static_cast<std::int64_t>(values.size());
    Field(size);
    if (reading_ && size != static_cast<std::int64_t>(values.size())) ok_ = false;
    for (std::size_t i = 0; ok_ && i < values.size(); ++i) Field(values[i]);
  }
  // A string or a vector of any length (the reader takes the written length).
  void Resizable(std::string& text);
  void Resizable(std::vector<double>& values);

 private:
  Archive(bool reading, std::string bytes) : reading_(reading), bytes_(std::move(bytes)) {}
  void Raw(void* data, std::size_t size);

  bool reading_;
  bool ok_ = true;
  std::string bytes_;
  std::size_t offset_ = 0;
};

inline void Archive::Raw(void* data, std::size_t size) {
  // Nothing to copy: an empty vector's data() may be null, which memcpy must not be given.
  if (size == 0) return;
  if (!ok_) return;
  if (!reading_) {
    bytes_.append(static_cast<const char*>(data), size);
    return;
  }
  if (bytes_.size() - offset_ < size) {
    ok_ = false;
    return;
  }
  std::memcpy(data, bytes_.data() + offset_, size);
  offset_ += size;
}

inline void Archive::Resizable(std::string& text) {
  std::int64_t size = static_cast<std::int64_t>(text.size());
  Field(size);
  if (reading_) {
    if (!ok_ || size < 0 || static_cast<std::size_t>(size) > bytes_.size() - offset_) {
      ok_ = false;
      return;
    }
    text.resize(static_cast<std::size_t>(size));
  }
  Raw(text.data(), text.size());
}

inline void Archive::Resizable(std::vector<double>& values) {
  std::int64_t size = static_cast<std::int64_t>(values.size());
  Field(size);
  if (reading_) {
    if (!ok_ || size < 0 ||
        static_cast<std::size_t>(size) > (bytes_.size() - offset_) / sizeof(double)) {
      ok_ = false;
      return;
    }
    values.resize(static_cast<std::size_t>(size));
  }
  Raw(values.data(), values.size() * sizeof(double));
}

}  // namespace sled::runtime
