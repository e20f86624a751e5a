// NumPy .npy reader (format of numpy.lib.format, versions 1.0 to 3.0):
//   "\x93NUMPY", major, minor; header length (uint16 LE for version 1, uint32
//   LE for 2 and 3); the header, a Python dict literal
//   {'descr': '<f4', 'fortran_order': False, 'shape': (64, 64, 2), }
//   padded with spaces and a newline; then the array's bytes.
#include <Imath/half.h>

#include <cstdint>
#include <cstring>
#include <string_view>

#include "brdflut/error.h"
#include "io/image_limits.h"
#include "io/readers.h"

namespace brdflut {
namespace {

struct Header {
    std::string descr;
    bool fortran = false, has_fortran = false, has_shape = false;
    std::vector<long long> shape;
};

// A parser of the header dict: string keys; values a string, True/False or a
// tuple of whole numbers. Returns an empty string or what is wrong.
class DictParser {
public:
    explicit DictParser(std::string_view s) : s_(s) {}
    std::string parse(Header& h) {
        skip();
        if (!eat('{')) return "the header is not a dict";
        for (;;) {
            skip();
            if (eat('}')) break;
            std::string key;
            if (!string(key)) return "a header key is not a string";
            skip();
            if (!eat(':')) return "no ':' after header key '" + key + "'";
            skip();
            if (key == "descr") {
                if (!string(h.descr)) return "'descr' is not a string (structured dtypes are not read)";
            } else if (key == "fortran_order") {
                if (word("True")) h.fortran = true;
                else if (!word("False")) return "'fortran_order' is neither True nor False";
                h.has_fortran = true;
            } else if (key == "shape") {
                if (!tuple(h.shape)) return "'shape' is not a tuple of whole numbers";
                h.has_shape = true;
            } else {
                return "unknown header key '" + key + "'";
            }
            skip();
            if (eat(',')) continue;
            skip();
            if (eat('}')) break;
            return "expected ',' or '}' in the header";
        }
        return {};
    }

private:
    std::string_view s_;
    std::size_t at_ = 0;
    void skip() {
        while (at_ < s_.size() && (s_[at_] == ' ' || s_[at_] == '\t' || s_[at_] == '\n' || s_[at_] == '\r')) ++at_;
    }
    bool eat(char c) {
        if (at_ < s_.size() && s_[at_] == c) {
            ++at_;
            return true;
        }
        return false;
    }
    bool word(std::string_view w) {
        if (s_.substr(at_, w.size()) != w) return false;
        at_ += w.size();
        return true;
    }
    bool string(std::string& out) {
        if (at_ >= s_.size() || (s_[at_] != '\'' && s_[at_] != '"')) return false;
        const char q = s_[at_++];
        const std::size_t end = s_.find(q, at_);
        if (end == std::string_view::npos || end - at_ > 64) return false;
        out = std::string(s_.substr(at_, end - at_));
        at_ = end + 1;
        return true;
    }
    bool tuple(std::vector<long long>& out) {
        if (!eat('(')) return false;
        for (;;) {
            skip();
            if (eat(')')) return true;
            long long v = 0;
            int digits = 0;
            while (at_ < s_.size() && s_[at_] >= '0' && s_[at_] <= '9') {
                if (++digits > 12) return false;
                v = v * 10 + (s_[at_++] - '0');
            }
            if (digits == 0 || out.size() >= 8) return false;
            if (at_ < s_.size() && s_[at_] == 'L') ++at_;  // Python 2 long
            out.push_back(v);
            skip();
            if (eat(')')) return true;
            if (!eat(',')) return false;
        }
    }
};

}  // namespace

ExrImage read_npy(const char* data, std::size_t size, const std::string& name, const ReadOptions& options) {
    auto fail = [&](const std::string& why) -> RuntimeError { return RuntimeError("cannot read '" + name + "': " + why); };
    const auto* u = reinterpret_cast<const unsigned char*>(data);
    if (size < 10) throw fail("the NumPy file is truncated");
    const int major = u[6], minor = u[7];
    if (major < 1 || major > 3)
        throw fail("NumPy format version " + std::to_string(major) + "." + std::to_string(minor) +
                   " is not read (versions 1 to 3 are)");
    std::size_t header_len = 0, header_at = 0;
    if (major == 1) {
        header_len = u[8] | static_cast<std::size_t>(u[9]) << 8;
        header_at = 10;
    } else {
        if (size < 12) throw fail("the NumPy file is truncated");
        header_len = u[8] | static_cast<std::size_t>(u[9]) << 8 | static_cast<std::size_t>(u[10]) << 16 |
                     static_cast<std::size_t>(u[11]) << 24;
        header_at = 12;
    }
    if (header_len > size - header_at) throw fail("the NumPy header is truncated");
    Header h;
    if (const std::string why = DictParser(std::string_view(data + header_at, header_len)).parse(h); !why.empty())
        throw fail("the NumPy header: " + why);
    if (h.descr.empty() || !h.has_shape || !h.has_fortran)
        throw fail("the NumPy header lacks 'descr', 'fortran_order' or 'shape'");
    if (h.fortran) throw fail("the array is in Fortran order; only C order is read");
    // descr: byte order, kind, item size.
    const std::string& d = h.descr;
    const std::string allowed = "allowed: f2, f4, f8, u1, u2, little- or big-endian";
    if (d.size() != 3 || (d[0] != '<' && d[0] != '>' && d[0] != '|'))
        throw fail("dtype '" + d + "' is not read; " + allowed);
    const bool big = d[0] == '>';
    const std::string type = d.substr(1);
    int item = 0;
    bool is_float = false;
    if (type == "f2" || type == "f4" || type == "f8") {
        is_float = true;
        item = type[1] - '0';
    } else if (type == "u1" || type == "u2") {
        item = type[1] - '0';
    } else {
        throw fail("dtype '" + d + "' is not read; " + allowed);
    }
    if (d[0] == '|' && item != 1) throw fail("dtype '" + d + "' has no byte order");
    // The shape, checked against the limits before anything is allocated.
    long long count = 1;
    std::string shape_text;
    for (long long v : h.shape) {
        shape_text += (shape_text.empty() ? "" : ", ") + std::to_string(v);
        if (v < 1) throw fail("the array's shape (" + shape_text + ") has an empty dimension");
        if (count > kMaxImageValues / v)
            throw fail("the array's shape (" + shape_text + ") holds more than the " + std::to_string(kMaxImageValues) +
                       " values of the largest image");
        count *= v;
    }
    if (h.shape.empty()) throw fail("the array is a scalar (shape ())");
    ArrayShape shape;
    if (const std::string why = resolve_shape(h.shape, count, options.shape, shape); !why.empty())
        throw fail("the array of shape (" + shape_text + ") " + why);
    ExrImage img;
    if (const std::string why = shape_image(img, shape); !why.empty()) throw fail(why);
    const std::size_t data_at = header_at + header_len;
    const std::uint64_t need = static_cast<std::uint64_t>(count) * static_cast<std::uint64_t>(item);
    if (size - data_at < need)
        throw fail("the array data is truncated: shape (" + shape_text + ") of '" + d + "' needs " +
                   std::to_string(need) + " bytes, the file has " + std::to_string(size - data_at));
    if (size - data_at > need)
        throw fail("the file has " + std::to_string(size - data_at - need) + " bytes after the array data");
    img.pixel = type == "f2" ? PixelType::half : PixelType::float32;
    if (type == "u1") img.storage = Storage::unorm8;
    if (type == "u2") img.storage = Storage::unorm16;
    img.pixels.resize(static_cast<std::size_t>(count));
    const unsigned char* p = u + data_at;
    for (std::size_t i = 0; i < img.pixels.size(); ++i, p += item) {
        std::uint64_t bits = 0;
        for (int b = 0; b < item; ++b) {
            const int k = big ? b : item - 1 - b;  // most significant byte first
            bits = bits << 8 | p[k];
        }
        double v = 0;
        if (!is_float) {
            v = static_cast<double>(bits) / (item == 1 ? 255.0 : 65535.0);
        } else if (item == 2) {
            Imath::half hv;
            hv.setBits(static_cast<unsigned short>(bits));
            v = static_cast<double>(static_cast<float>(hv));
        } else if (item == 4) {
            const std::uint32_t b32 = static_cast<std::uint32_t>(bits);
            float f;
            std::memcpy(&f, &b32, sizeof f);
            v = static_cast<double>(f);
        } else {
            std::memcpy(&v, &bits, sizeof v);
        }
        img.pixels[i] = v;
    }
    interleave_planes(img, shape);
    return img;
}

}  // namespace brdflut
