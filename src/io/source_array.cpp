// Numeric arrays in source files: C, C++, GLSL, HLSL and JavaScript.
//
// A declaration is a name, optional dimensions in brackets, '=' and an
// initializer:
//   static const float table_ggx_E[1024] = { 1.0f, 0.98f, ... };
//   const float bsdf_split_sum_ggx[64][64][2] = {{{0.1f, 0.2f}, ...}};
//   static const float2 lut[256] = { float2(0.1, 0.2), ... };      (HLSL)
//   const vec2 lut[2] = vec2[2](vec2(0.1, 0.2), vec2(0.3, 0.4)); (GLSL)
//   const LTC_MAT_1 = [ 1, 0, 0, 2e-05, ... ];                     (JavaScript)
//   const ltc = new Float32Array( [ ... ] );
// The initializer is a group in braces, brackets or parentheses, after an
// optional `new TypedArray(` or `Type[...](`; its elements are numbers
// (signed, decimal or hexadecimal, with exponents and the suffixes f, F, h,
// H, l, L, u, U), groups, or constructor calls such as vec2(...) or
// float2(...), which count as groups. Comments, strings and preprocessor
// lines are skipped.
//
// The shape, unless given: the declared dimensions (a dimension may be a
// product such as 64 * 64 * 2; a first one left empty is count / the rest;
// a vector element type vecN, floatN, halfN, doubleN adds a last dimension
// N, the channels), or else the nesting of the initializer when it is
// regular; then resolve_shape() (readers.h). Numbers are held as written
// (double).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string_view>

#include "brdflut/error.h"
#include "io/image_limits.h"
#include "io/readers.h"

namespace brdflut {
namespace {

enum class Tok { ident, number, punct, end };

struct Token {
    Tok kind = Tok::end;
    std::string_view text;
    int line = 1;
};

bool ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '$'; }
bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9'); }
bool digit(char c) { return c >= '0' && c <= '9'; }

class Lexer {
public:
    Lexer(std::string_view s) : s_(s) {}
    Token next() {
        skip_space_and_comments();
        Token t;
        t.line = line_;
        if (at_ >= s_.size()) return t;
        const std::size_t start = at_;
        const char c = s_[at_];
        if (ident_start(c)) {
            while (at_ < s_.size() && ident_char(s_[at_])) ++at_;
            t.kind = Tok::ident;
        } else if (digit(c) || (c == '.' && at_ + 1 < s_.size() && digit(s_[at_ + 1]))) {
            const bool hex = c == '0' && at_ + 1 < s_.size() && (s_[at_ + 1] == 'x' || s_[at_ + 1] == 'X');
            while (at_ < s_.size()) {
                const char d = s_[at_];
                if (ident_char(d) || d == '.') {
                    ++at_;
                } else if ((d == '+' || d == '-') && at_ > start) {
                    const char e = s_[at_ - 1];
                    if ((!hex && (e == 'e' || e == 'E')) || (hex && (e == 'p' || e == 'P'))) ++at_;
                    else break;
                } else {
                    break;
                }
            }
            t.kind = Tok::number;
        } else {
            ++at_;
            // Two-character operators, so that a lone '=' is an assignment.
            if (at_ < s_.size() && s_[at_] == '=' && std::string_view("=!<>+-*/%&|^").find(c) != std::string_view::npos)
                ++at_;
            else if (c == '=' && at_ < s_.size() && s_[at_] == '>')
                ++at_;
            t.kind = Tok::punct;
        }
        t.text = s_.substr(start, at_ - start);
        return t;
    }
    int line() const { return line_; }

private:
    std::string_view s_;
    std::size_t at_ = 0;
    int line_ = 1;
    bool line_start_ = true;

    void skip_space_and_comments() {
        while (at_ < s_.size()) {
            const char c = s_[at_];
            if (c == '\n') {
                ++line_;
                ++at_;
                line_start_ = true;
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
                ++at_;
            } else if (c == '/' && at_ + 1 < s_.size() && s_[at_ + 1] == '/') {
                while (at_ < s_.size() && s_[at_] != '\n') ++at_;
            } else if (c == '/' && at_ + 1 < s_.size() && s_[at_ + 1] == '*') {
                at_ += 2;
                while (at_ < s_.size() && !(s_[at_] == '*' && at_ + 1 < s_.size() && s_[at_ + 1] == '/')) {
                    if (s_[at_] == '\n') ++line_;
                    ++at_;
                }
                at_ = std::min(s_.size(), at_ + 2);
            } else if (c == '#' && line_start_) {
                // A preprocessor line, with its backslash continuations.
                while (at_ < s_.size() && s_[at_] != '\n') {
                    if (s_[at_] == '\\' && at_ + 1 < s_.size() && s_[at_ + 1] == '\n') {
                        ++line_;
                        ++at_;
                    }
                    ++at_;
                }
            } else if (c == '"' || c == '\'' || c == '`') {
                ++at_;
                while (at_ < s_.size() && s_[at_] != c) {
                    if (s_[at_] == '\\') ++at_;
                    else if (s_[at_] == '\n') ++line_;
                    ++at_;
                }
                at_ = std::min(s_.size(), at_ + 1);
                line_start_ = false;
            } else {
                line_start_ = false;
                return;
            }
        }
    }
};

// The value of a number token, or false when it is not one.
bool number_value(std::string_view t, double& v) {
    std::string_view body = t;
    const bool hex = t.size() > 2 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X');
    if (hex) body = t.substr(2);
    const char* end = body.data() + body.size();
    std::from_chars_result r{};
    if (hex) {
        const bool is_float = body.find_first_of(".pP") != std::string_view::npos;
        if (is_float) {
            r = std::from_chars(body.data(), end, v, std::chars_format::hex);
        } else {
            std::uint64_t i = 0;
            r = std::from_chars(body.data(), end, i, 16);
            v = static_cast<double>(i);
        }
    } else {
        // A leading 0 followed by digits only would be octal in C.
        if (t.size() > 1 && t[0] == '0' && digit(t[1]) && t.find_first_of(".eE") == std::string_view::npos) return false;
        r = std::from_chars(body.data(), end, v, std::chars_format::general);
    }
    if (r.ec != std::errc() || r.ptr == body.data()) return false;
    const std::string_view suffix(r.ptr, static_cast<std::size_t>(end - r.ptr));
    if (suffix.size() > 3) return false;
    for (char c : suffix)
        if (std::string_view("fFhHlLuU").find(c) == std::string_view::npos) return false;
    return true;
}

// The count of digits after the point of a number printed in fixed point
// ("0.998773f": 6), or -1 for one with an exponent or in hex.
int fixed_decimals(std::string_view t) {
    if (t.size() > 1 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) return -1;
    if (t.find_first_of("eE") != std::string_view::npos) return -1;
    const std::size_t dot = t.find('.');
    int decimals = 0;
    if (dot != std::string_view::npos)
        for (std::size_t i = dot + 1; i < t.size() && digit(t[i]); ++i) ++decimals;
    return decimals;
}

// Vector element types: their component count, else 0.
long long vector_size(std::string_view type) {
    for (std::string_view prefix : {"vec", "dvec", "float", "half", "double", "min16float"})
        if (type.size() == prefix.size() + 1 && type.substr(0, prefix.size()) == prefix) {
            const char n = type.back();
            if (n >= '2' && n <= '4') return n - '0';
        }
    return 0;
}

constexpr int kMaxNesting = 8;

struct Shape {
    bool regular = true;
    std::vector<long long> dims;  // outermost first; empty for a number
};

class ArrayParser {
public:
    ArrayParser(Lexer& lex, const std::string& file, const std::string& array, std::vector<double>& out)
        : lex_(lex), file_(file), array_(array), out_(out) {}

    [[noreturn]] void fail(int line, const std::string& why) const {
        throw RuntimeError("cannot read '" + file_ + "': array '" + array_ + "' (line " + std::to_string(line) +
                           "): " + why);
    }

    // A group whose opening token has been read; returns its shape.
    Shape group(char open, int depth) {
        if (depth > kMaxNesting) fail(lex_.line(), "nested deeper than " + std::to_string(kMaxNesting) + " levels");
        const char close = open == '{' ? '}' : open == '[' ? ']' : ')';
        Shape s;
        long long n = 0;
        bool first = true;
        std::vector<long long> child;
        for (;;) {
            Token t = lex_.next();
            if (t.kind == Tok::punct && t.text.size() == 1 && t.text[0] == close) break;  // also after a trailing ','
            Shape e = element(t, depth);
            ++n;
            if (first) child = e.dims;
            else if (!e.regular || e.dims != child) s.regular = false;
            if (!e.regular) s.regular = false;
            first = false;
            t = lex_.next();
            if (t.kind == Tok::punct && t.text.size() == 1 && t.text[0] == close) break;
            if (!(t.kind == Tok::punct && t.text == ",")) fail(t.line, "expected ',' or '" + std::string(1, close) + "', found " + describe(t));
        }
        s.dims.push_back(n);
        s.dims.insert(s.dims.end(), child.begin(), child.end());
        return s;
    }

    // The unit of the last printed digit when every number was printed in
    // fixed point with the same count of decimals (as printf's "%.6f"), the
    // resolution the array was printed with; 0 otherwise (shortest digits,
    // exponents, mixed counts), when the values are taken as floats.
    double step() const { return decimals_ > 0 ? std::pow(10.0, -decimals_) : 0.0; }

private:
    Lexer& lex_;
    const std::string& file_;
    const std::string& array_;
    std::vector<double>& out_;
    int decimals_ = -2;  // -2: no number yet; -1: not one fixed count

    static std::string describe(const Token& t) {
        if (t.kind == Tok::end) return "the end of the file";
        std::string out(1, '\'');
        out.append(t.text.substr(0, 40));
        out += '\'';
        return out;
    }

    Shape element(Token t, int depth) {
        if (t.kind == Tok::punct && (t.text == "{" || t.text == "[" || t.text == "(")) return group(t.text[0], depth + 1);
        if (t.kind == Tok::ident) {
            // A constructor call: vec2(...), float2(...), float(...).
            const Token open = lex_.next();
            if (open.kind == Tok::punct && open.text == "(") return group('(', depth + 1);
            fail(t.line, "expected a number, found " + describe(t));
        }
        double sign = 1;
        if (t.kind == Tok::punct && (t.text == "-" || t.text == "+")) {
            sign = t.text == "-" ? -1 : 1;
            t = lex_.next();
        }
        double v = 0;
        if (t.kind != Tok::number || !number_value(t.text, v)) fail(t.line, "expected a number, found " + describe(t));
        if (static_cast<long long>(out_.size()) >= kMaxImageValues)
            fail(t.line, "holds more than the " + std::to_string(kMaxImageValues) + " values of the largest image");
        out_.push_back(sign * v);
        // Fixed-point printing: every number with the same count of decimals.
        const int d = fixed_decimals(t.text);
        if (decimals_ == -2) decimals_ = d;
        else if (decimals_ != d) decimals_ = -1;
        return {};
    }
};

// Declared dimensions: each a product of whole numbers, or empty (-1), or
// unknown (a macro: -2).
long long dimension_value(const std::vector<Token>& toks) {
    if (toks.empty()) return -1;
    long long v = 1;
    bool expect_number = true;
    for (const Token& t : toks) {
        if (expect_number) {
            double d = 0;
            if (t.kind != Tok::number || !number_value(t.text, d) || d < 0 || d > 1e12 || d != static_cast<long long>(d))
                return -2;
            const long long k = static_cast<long long>(d);
            if (k != 0 && v > (1LL << 40) / k) return -2;
            v *= k;
        } else if (t.text != "*") {
            return -2;
        }
        expect_number = !expect_number;
    }
    return expect_number ? -2 : v;
}

}  // namespace

ExrImage read_source_array(const char* data, std::size_t size, const std::string& name, const ReadOptions& options) {
    auto fail = [&](const std::string& why) -> RuntimeError { return RuntimeError("cannot read '" + name + "': " + why); };
    const std::string& want = options.array;
    if (want.empty()) throw fail("no array name given (--array NAME)");
    Lexer lex(std::string_view(data, size));
    // The tokens since the last ';', '{' or '}' at statement level, so that a
    // declaration can be looked at when its '=' is reached.
    std::vector<Token> stmt;
    std::vector<std::string> names;
    std::vector<double> values;
    for (Token t = lex.next(); t.kind != Tok::end; t = lex.next()) {
        if (t.kind == Tok::punct && (t.text == ";" || t.text == "{" || t.text == "}" || t.text == ",")) {
            stmt.clear();
            continue;
        }
        if (!(t.kind == Tok::punct && t.text == "=")) {
            if (stmt.size() < 64) stmt.push_back(t);
            else stmt.clear();  // not a declaration this parser reads
            continue;
        }
        // name [dims]... = ; walk back over the bracket groups.
        std::vector<std::vector<Token>> dim_tokens;
        std::size_t i = stmt.size();
        while (i > 0 && stmt[i - 1].kind == Tok::punct && stmt[i - 1].text == "]") {
            std::size_t j = i - 1;
            while (j > 0 && !(stmt[j - 1].kind == Tok::punct && stmt[j - 1].text == "[")) --j;
            if (j == 0) break;
            dim_tokens.insert(dim_tokens.begin(), std::vector<Token>(stmt.begin() + static_cast<std::ptrdiff_t>(j),
                                                                     stmt.begin() + static_cast<std::ptrdiff_t>(i - 1)));
            i = j - 1;
        }
        if (i == 0 || stmt[i - 1].kind != Tok::ident) {
            stmt.clear();
            continue;
        }
        const Token decl = stmt[i - 1];
        const std::string_view type = i >= 2 && stmt[i - 2].kind == Tok::ident ? stmt[i - 2].text : std::string_view();
        stmt.clear();
        // The initializer: `new X(`, `Type[...](` or a group directly.
        Token open = lex.next();
        if (open.kind == Tok::ident && open.text == "new") {
            lex.next();         // the typed array's name
            open = lex.next();  // '('
            if (open.kind == Tok::punct && open.text == "(") {
                const Token inner = lex.next();
                if (inner.kind == Tok::punct && inner.text == "[") open = inner;
                else continue;  // new Float32Array(other_array): not an initializer
            }
        } else if (open.kind == Tok::ident) {
            // GLSL array constructors: float[](...), vec2[4](...).
            Token b = lex.next();
            if (!(b.kind == Tok::punct && b.text == "[")) continue;
            while (b.kind == Tok::punct && b.text == "[") {
                b = lex.next();
                while (b.kind == Tok::number || (b.kind == Tok::punct && b.text == "*")) b = lex.next();
                if (!(b.kind == Tok::punct && b.text == "]")) break;
                b = lex.next();
            }
            open = b;
        }
        if (!(open.kind == Tok::punct && (open.text == "{" || open.text == "[" || open.text == "("))) continue;
        if (decl.text != want) {
            // Another array, or an expression in parentheses or brackets:
            // read it into a scratch buffer; it is listed if it is an array.
            std::vector<double> scratch;
            try {
                ArrayParser(lex, name, std::string(decl.text), scratch).group(open.text[0], 1);
                if (std::find(names.begin(), names.end(), decl.text) == names.end()) names.emplace_back(decl.text);
            } catch (const RuntimeError&) {
                // not an array initializer; scanning goes on from here
            }
            continue;
        }
        ArrayParser parser(lex, name, want, values);
        const Shape nested = parser.group(open.text[0], 1);
        const double parser_step = parser.step();
        const long long count = static_cast<long long>(values.size());
        if (count == 0) throw fail("array '" + want + "' (line " + std::to_string(decl.line) + ") is empty");
        // Declared dimensions.
        std::vector<long long> dims;
        bool known = !dim_tokens.empty();
        for (const auto& d : dim_tokens) {
            dims.push_back(dimension_value(d));
            if (dims.back() == -2) known = false;
        }
        const long long vn = vector_size(type);
        if (vn > 0 && known) dims.push_back(vn);
        if (known) {
            long long rest = 1;
            for (std::size_t k = 1; k < dims.size(); ++k) {
                if (dims[k] < 1) known = false;
                else rest *= dims[k];
            }
            // An empty first dimension: the nesting when it is regular and
            // ends in the declared ones, else count / the rest.
            if (known && dims[0] == -1 && nested.regular && nested.dims.size() >= dims.size() &&
                std::equal(dims.begin() + 1, dims.end(), nested.dims.end() - static_cast<std::ptrdiff_t>(dims.size() - 1)))
                dims = nested.dims;
            else if (known && dims[0] == -1 && rest > 0 && count % rest == 0)
                dims[0] = count / rest;
            long long product = 1;
            for (long long d : dims) product = d > 0 ? product * d : 0;
            if (known && product != count) {
                std::string declared;
                for (long long d : dims) {
                    declared += '[';
                    if (d >= 0) declared += std::to_string(d);
                    declared += ']';
                }
                throw fail("array '" + want + "' (line " + std::to_string(decl.line) + ") is declared " + declared +
                           " (" + std::to_string(product) + " values) but its initializer holds " +
                           std::to_string(count) + " numbers");
            }
        }
        if (!known) dims = nested.regular ? nested.dims : std::vector<long long>{count};
        const bool vector_channels = vn > 0 && dims.size() >= 2 && dims.back() == vn;
        ArrayShape shape;
        if (const std::string why = resolve_shape(dims, count, options.shape, shape, vector_channels); !why.empty())
            throw fail("array '" + want + "' (line " + std::to_string(decl.line) + ") " + why);
        ExrImage img;
        if (const std::string why = shape_image(img, shape); !why.empty())
            throw fail("array '" + want + "': " + why);
        img.pixel = PixelType::float32;
        img.pixels = std::move(values);
        interleave_planes(img, shape);
        img.printed_step = parser_step;
        return img;
    }
    std::string list;
    for (std::size_t k = 0; k < names.size() && k < 30; ++k) list += (k ? ", " : "") + names[k];
    if (names.size() > 30) list += " and " + std::to_string(names.size() - 30) + " more";
    throw fail("no array '" + want + "' in the file; " +
               (names.empty() ? std::string("it has no array initializers") : "its arrays: " + list));
}

}  // namespace brdflut
