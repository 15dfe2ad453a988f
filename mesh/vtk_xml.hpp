#pragma once
// The pieces the VTK XML writers share (vtu_writer, vtp_writer): array shape
// checks, XML escaping and the DataArray elements in ASCII or VTK's inline
// binary. Internal to mesh/.
#include "sinew/mesh/base64.hpp"
#include "sinew/mesh/vtu_writer.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace sinew::vtk_xml {

inline std::string shape(const Eigen::MatrixXd& values)
{
    return std::to_string(values.rows()) + "x" + std::to_string(values.cols());
}

/// std::invalid_argument (a caller's bug) for an array without a name or of another shape than 1–3 × count.
inline void check_arrays(const std::string& writer_name, const VtuArrays& arrays, Eigen::Index count,
                         const std::string& what)
{
    for (const auto& [name, values] : arrays) {
        if (name.empty())
            throw std::invalid_argument(writer_name + ": a " + what + " array has an empty name");
        if (values.rows() < 1 || values.rows() > 3 || values.cols() != count)
            throw std::invalid_argument(writer_name + ": " + what + " array '" + name + "' is " + shape(values) +
                                        ", expected 1, 2 or 3 components x " + std::to_string(count));
    }
}

inline std::string xml_escaped(const std::string& text)
{
    std::string escaped;
    for (char c : text) {
        switch (c) {
        case '&': escaped += "&amp;"; break;
        case '<': escaped += "&lt;"; break;
        case '>': escaped += "&gt;"; break;
        case '"': escaped += "&quot;"; break;
        case '\'': escaped += "&apos;"; break;
        default: escaped += c;
        }
    }
    return escaped;
}

/// Emits DataArray elements in one encoding.
class DataArrayWriter {
public:
    DataArrayWriter(std::ofstream& out, VtuEncoding encoding) : out_(out), encoding_(encoding) {}

    /// A Float64 array of the columns of `values`, 2-component columns padded
    /// with a zero third component. `name` empty: no Name attribute.
    void float64(const std::string& name, const Eigen::MatrixXd& values)
    {
        const Eigen::Index components = values.rows() == 2 ? 3 : values.rows();
        std::vector<double> data;
        data.reserve(static_cast<size_t>(components * values.cols()));
        for (Eigen::Index j = 0; j < values.cols(); ++j)
            for (Eigen::Index i = 0; i < components; ++i)
                data.push_back(i < values.rows() ? values(i, j) : 0.0);
        write("Float64", name, components, data, values.cols() > 0 ? static_cast<size_t>(components) : 1);
    }

    /// An integer array of `type` Int64 or UInt8, `per_line` values a line in ASCII.
    template <typename Integer>
    void integers(const char* type, const std::string& name, const std::vector<Integer>& data, size_t per_line)
    {
        write(type, name, 1, data, per_line);
    }

private:
    template <typename Value>
    void write(const char* type, const std::string& name, Eigen::Index components, const std::vector<Value>& data,
               size_t per_line)
    {
        out_ << "        <DataArray type=\"" << type << "\"";
        if (!name.empty())
            out_ << " Name=\"" << xml_escaped(name) << "\"";
        if (components > 1 || std::is_same<Value, double>::value)
            out_ << " NumberOfComponents=\"" << components << "\"";
        out_ << " format=\"" << (encoding_ == VtuEncoding::ascii ? "ascii" : "binary") << "\">\n";
        if (encoding_ == VtuEncoding::ascii) {
            for (size_t k = 0; k < data.size(); ++k)
                out_ << (k % per_line == 0 ? "" : " ") << +data[k] << (k % per_line == per_line - 1 ? "\n" : "");
        } else {
            // base64 of (UInt32 byte count, the values), little-endian as the header says.
            const std::uint32_t bytes = static_cast<std::uint32_t>(data.size() * sizeof(Value));
            std::vector<unsigned char> block(sizeof bytes + bytes);
            std::memcpy(block.data(), &bytes, sizeof bytes);
            if (bytes > 0)
                std::memcpy(block.data() + sizeof bytes, data.data(), bytes);
            out_ << base64(block.data(), block.size()) << "\n";
        }
        out_ << "        </DataArray>\n";
    }

    std::ofstream& out_;
    VtuEncoding encoding_;
};

inline void write_data_arrays(DataArrayWriter& writer, std::ofstream& out, const VtuArrays& arrays, const std::string& section)
{
    if (arrays.empty())
        return;
    out << "      <" << section << ">\n";
    for (const auto& [name, values] : arrays)
        writer.float64(name, values);
    out << "      </" << section << ">\n";
}

} // namespace sinew::vtk_xml
