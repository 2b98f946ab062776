#include "io/vtk_data_array.hpp"

#include <array>
#include <bit>
#include <iomanip>
#include <stdexcept>

namespace rbcsim::io {
namespace {

// The binary format stores the machine's bytes as they are and declares them little-endian.
static_assert(std::endian::native == std::endian::little,
              "VTK base64 output assumes a little-endian machine");

constexpr int kSignificantDigits = 9;

template <typename T>
struct VtkType;
template <>
struct VtkType<double> {
  static constexpr std::string_view name = "Float64";
};
template <>
struct VtkType<std::int32_t> {
  static constexpr std::string_view name = "Int32";
};
template <>
struct VtkType<std::int64_t> {
  static constexpr std::string_view name = "Int64";
};
template <>
struct VtkType<std::uint8_t> {
  static constexpr std::string_view name = "UInt8";
};

// Base64 (RFC 4648) of a byte stream given in pieces, written as it goes.
class Base64Writer {
 public:
  explicit Base64Writer(std::ostream& out) : out_(out) {}

  void write(const void* data, std::size_t count) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < count; ++i) {
      pending_[pending_count_++] = bytes[i];
      if (pending_count_ == 3) emit_group();
    }
  }

  // Encodes the last one or two bytes with '=' padding and flushes.
  void finish() {
    if (pending_count_ > 0) emit_group();
    out_.write(encoded_.data(), static_cast<std::streamsize>(encoded_.size()));
    encoded_.clear();
  }

 private:
  static constexpr std::string_view kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  static constexpr std::size_t kFlushSize = 1 << 16;

  // Three bytes (the missing ones of a final group taken as zero) to four characters; a final
  // group of n < 3 bytes keeps n + 1 of them and is padded with '='.
  void emit_group() {
    for (int i = pending_count_; i < 3; ++i) pending_[i] = 0;
    const unsigned group =
        (unsigned{pending_[0]} << 16) | (unsigned{pending_[1]} << 8) | unsigned{pending_[2]};
    for (int k = 0; k < 4; ++k) {
      encoded_.push_back(k <= pending_count_ ? kAlphabet[(group >> (18 - 6 * k)) & 63] : '=');
    }
    pending_count_ = 0;
    if (encoded_.size() >= kFlushSize) {
      out_.write(encoded_.data(), static_cast<std::streamsize>(encoded_.size()));
      encoded_.clear();
    }
  }

  std::ostream& out_;
  std::array<unsigned char, 3> pending_{};
  int pending_count_ = 0;
  std::string encoded_;
};

template <typename T>
void write_values(std::ostream& out, std::span<const T> values, int component_count,
                  VtkEncoding encoding, std::string_view indent) {
  if (encoding == VtkEncoding::base64) {
    // VTK's inline binary layout: the byte count as header_type (UInt64), then the raw values,
    // encoded as one base64 stream.
    const std::uint64_t byte_count = values.size_bytes();
    Base64Writer writer(out);
    out << indent << "  ";
    writer.write(&byte_count, sizeof(byte_count));
    writer.write(values.data(), values.size_bytes());
    writer.finish();
    out << '\n';
    return;
  }
  const auto per_line = static_cast<std::size_t>(component_count);
  for (std::size_t first = 0; first < values.size(); first += per_line) {
    out << indent << ' ';
    for (std::size_t k = first; k < first + per_line && k < values.size(); ++k) {
      // Bytes are numbers, not characters.
      if constexpr (sizeof(T) == 1) {
        out << ' ' << static_cast<int>(values[k]);
      } else {
        out << ' ' << values[k];
      }
    }
    out << '\n';
  }
}

}  // namespace

std::size_t DataArray::value_count() const {
  return std::visit([](const auto& span) { return span.size(); }, values);
}

PointDataArray scalar_point_array(std::string name, std::span<const double> values) {
  return {std::move(name), 1, values};
}

PointDataArray vector_point_array(std::string name, std::span<const Vec3> values) {
  // Eigen::Vector3d is three contiguous doubles without padding.
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  return {
      std::move(name), 3,
      std::span<const double>(values.empty() ? nullptr : values.front().data(), 3 * values.size())};
}

PointDataArray byte_point_array(std::string name, std::span<const std::uint8_t> values) {
  return {std::move(name), 1, values};
}

void check_point_arrays(std::size_t point_count, std::span<const PointDataArray> arrays) {
  for (const auto& array : arrays) {
    if (array.name.empty() || array.name.find_first_of("<>&\"'") != std::string::npos) {
      throw std::invalid_argument("VTK point array name '" + array.name +
                                  "' must be non-empty plain text (no XML markup characters)");
    }
    if (array.component_count != 1 && array.component_count != 3) {
      throw std::invalid_argument("VTK point array '" + array.name +
                                  "' must have 1 or 3 components");
    }
    if (array.value_count() != point_count * static_cast<std::size_t>(array.component_count)) {
      throw std::invalid_argument("VTK point array '" + array.name + "' has " +
                                  std::to_string(array.value_count()) + " values for " +
                                  std::to_string(point_count) + " points");
    }
  }
}

std::string_view vtk_file_attributes() {
  return "byte_order=\"LittleEndian\" header_type=\"UInt64\"";
}

void write_data_array(std::ostream& out, const DataArray& array, VtkEncoding encoding,
                      std::string_view indent) {
  std::visit(
      [&](const auto& values) {
        using Value = typename std::decay_t<decltype(values)>::value_type;
        out << std::setprecision(kSignificantDigits);
        out << indent << "<DataArray type=\"" << VtkType<std::remove_const_t<Value>>::name
            << "\" Name=\"" << array.name << '"';
        if (array.component_count != 1) {
          out << " NumberOfComponents=\"" << array.component_count << '"';
        }
        out << " format=\"" << (encoding == VtkEncoding::ascii ? "ascii" : "binary") << "\">\n";
        write_values(out, values, array.component_count, encoding, indent);
        out << indent << "</DataArray>\n";
      },
      array.values);
}

}  // namespace rbcsim::io
