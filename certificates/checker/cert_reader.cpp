// cert_reader.cpp — trusted core: the lexical layer of the certificate. Reads the file line
// by line with getline(3), feeds every byte to a SHA-256 context, and refuses anything that
// is not exactly in the canonical form of FORMAT.md.
#include "checker.h"

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace cc {

void malformed(long record, const std::string& why) { throw CertError(true, record, why); }
void rejected(long record, const std::string& why) { throw CertError(false, record, why); }

static std::string hex_digest(EVP_MD_CTX* md) {
  unsigned char d[EVP_MAX_MD_SIZE];
  unsigned len = 0;
  EVP_DigestFinal_ex(md, d, &len);
  static const char* x = "0123456789abcdef";
  std::string s;
  for (unsigned i = 0; i < len; ++i) {
    s += x[d[i] >> 4];
    s += x[d[i] & 15];
  }
  return s;
}

std::string sha256_hex(const std::string& bytes) {
  EVP_MD_CTX* md = EVP_MD_CTX_new();
  EVP_DigestInit_ex(md, EVP_sha256(), nullptr);
  EVP_DigestUpdate(md, bytes.data(), bytes.size());
  std::string s = hex_digest(md);
  EVP_MD_CTX_free(md);
  return s;
}

static const char kUnreadable[] =
    "cannot read the file (a read error, or compressed data corrupt or truncated)";

LineReader::LineReader(FILE* f) : f_(decompressed(f)) {
  md_ = EVP_MD_CTX_new();
  EVP_DigestInit_ex(md_, EVP_sha256(), nullptr);
}

LineReader::~LineReader() {
  if (f_) std::fclose(f_);
  EVP_MD_CTX_free(md_);
  std::free(line_buf_);
}

LineReader& LineReader::next() {
  finish_print();
  EVP_DigestUpdate(md_, bytes_read_.data(), bytes_read_.size());  // a binary record's
  bytes_read_.clear();
  binary_ = false;
  if (allow_binary_) {
    const int c = std::getc(f_);
    if (c >= 0x80) {
      ++line_;
      bytes_read_ += char(c);
      decode(c);
      bytes_ += bytes_read_.size();
      pos_ = 0;
      binary_ = true;
      printed_ = false;
      return *this;
    }
    if (c != EOF) std::ungetc(c, f_);
  }
  ssize_t n = getline(&line_buf_, &line_cap_, f_);
  ++line_;
  if (std::ferror(f_))  // also after a partial line
    malformed(line_, kUnreadable);
  if (n <= 0) malformed(line_, "unexpected end of file");
  bytes_ += uint64_t(n);
  EVP_DigestUpdate(md_, line_buf_, size_t(n));
  if (print_) std::fwrite(line_buf_, 1, size_t(n), stdout);
  if (line_buf_[n - 1] != '\n') malformed(line_, "truncated record (no newline at end of file)");
  fields_.clear();
  size_t start = 0;
  const size_t len = size_t(n - 1);
  for (size_t i = 0; i <= len; ++i) {
    // A space after the last byte closes the last field.
    const unsigned char c = i < len ? (unsigned char)line_buf_[i] : ' ';
    if (c != ' ' && (c < 0x21 || c > 0x7e))
      malformed(line_, "byte " + std::to_string(c) + " is not printable ASCII");
    if (c != ' ') continue;
    if (i == start) malformed(line_, len ? "leading, trailing or double space" : "empty line");
    fields_.emplace_back(line_buf_ + start, i - start);
    start = i + 1;
  }
  pos_ = 1;
  // Format 3 writes these records in binary only: a text one is a version 2 file relabelled.
  static const char* const compact[] = {"P", "B", "X", "U", "N", "S", "K", "csnc"};
  for (const char* k : compact)
    if (allow_binary_ && fields_[0] == k)
      malformed(line_, std::string("a text '") + k + "' record in a format 3 certificate");
  return *this;
}

std::string LineReader::raw(size_t n) {
  std::string s(n, '\0');
  if (n && std::fread(&s[0], 1, n, f_) != n) malformed(line_ + 1, "model text truncated");
  EVP_DigestUpdate(md_, s.data(), n);
  bytes_ += n + 1;
  if (print_) std::printf("%s\n", s.c_str());
  // Printable ASCII, tabs and newlines only, as the rest of the file: a '\r' (or another
  // control or non-ASCII byte, e.g. a bidi override) inside a comment makes the model
  // display differently from what the checker parses ("l = 1 #\rl = 2" shows l = 2).
  for (char c : s) {
    if (c == '\n') ++line_;
    const unsigned char u = (unsigned char)c;
    if (u != '\n' && u != '\t' && (u < 0x20 || u > 0x7e))
      malformed(line_ + 1,
                "byte " + std::to_string(u) + " in the model text is not printable ASCII");
  }
  int c = std::fgetc(f_);  // the model text is followed by exactly one '\n'
  if (c != '\n') malformed(line_ + 1, "model text not followed by a newline (wrong byte count?)");
  EVP_DigestUpdate(md_, "\n", 1);
  ++line_;
  return s;
}

void LineReader::expect_eof() {
  finish_print();
  if (std::fgetc(f_) != EOF) malformed(line_ + 1, "content after 'end'");
  // A compressed file is whole only once its frame's end and checksum were read.
  if (std::ferror(f_)) malformed(line_ + 1, kUnreadable);
}

std::string LineReader::file_sha256() {
  EVP_DigestUpdate(md_, bytes_read_.data(), bytes_read_.size());
  bytes_read_.clear();
  return hex_digest(md_);
}

// At most 18 digits, so that the value fits an int64_t without overflow checks.
int64_t parse_int(std::string_view s, long rec) {
  const size_t i = s[0] == '-' ? 1 : 0;
  const size_t digits = s.size() - i;
  bool ok = digits >= 1 && digits <= 18;
  ok = ok && !(s[i] == '0' && digits > 1) && s != "-0";
  int64_t v = 0;
  for (size_t k = i; ok && k < s.size(); ++k) {
    ok = s[k] >= '0' && s[k] <= '9';
    v = 10 * v + (s[k] - '0');
  }
  if (!ok) malformed(rec, "bad integer '" + std::string(s) + "'");
  return i ? -v : v;
}

// A real is exactly what glibc's printf("%a") prints for a finite double (FORMAT.md): no
// decimal form, no redundant zero, no upper case, no infinity or NaN. Read by its grammar,
// which only that form passes: [-]0x1[.F]p±E for a normal double (E in -1022..1023),
// [-]0x0.Fp-1022 for a subnormal one, [-]0x0p+0 for zero; F holds 1 to 13 lower-case hex
// digits, the last not 0, and E has no leading zero. The value is then exact.
double parse_real(std::string_view s, long rec) {
  const auto hex = [](char c) {
    return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
  };
  const size_t n = s.size();
  size_t i = n && s[0] == '-';
  bool ok = n >= i + 6 && s[i] == '0' && s[i + 1] == 'x' && (s[i + 2] == '0' || s[i + 2] == '1');
  const bool normal = ok && s[i + 2] == '1';
  i += 3;
  uint64_t frac = 0;
  int digits = 0;
  if (ok && s[i] == '.') {
    for (++i; i < n && hex(s[i]) >= 0; ++i, ++digits) frac = 16 * frac + uint64_t(hex(s[i]));
    ok = digits >= 1 && digits <= 13 && s[i - 1] != '0';
  }
  ok = ok && i + 2 < n && s[i] == 'p' && (s[i + 1] == '+' || s[i + 1] == '-');
  const bool minus = ok && s[i + 1] == '-';
  i += 2;
  ok = ok && n - i <= 4 && !(s[i] == '0' && n - i > 1);
  int e = 0;
  for (; ok && i < n; ++i) {
    ok = s[i] >= '0' && s[i] <= '9';
    e = 10 * e + (s[i] - '0');
  }
  if (minus) e = -e;
  // Only a well-formed fraction (1 to 13 digits) is shifted: a longer one would shift by a
  // negative count.
  const uint64_t mant = ok && digits ? frac << (52 - 4 * digits) : 0;
  if (normal) ok = ok && e >= -1022 && e <= 1023 && !(minus && e == 0);
  else ok = ok && (digits ? minus && e == -1022 : !minus && e == 0);
  if (!ok) malformed(rec, "bad real '" + std::string(s) + "' (expected a %a hexadecimal float)");
  const double v = normal ? std::ldexp(double((uint64_t(1) << 52) | mant), e - 52)
                          : std::ldexp(double(mant), -1074);
  return s[0] == '-' ? -v : v;
}

LineReader& LineReader::expect(const std::vector<const char*>& words, size_t extra) {
  next();
  return require(words, extra);
}

LineReader& LineReader::require(const std::vector<const char*>& words, size_t extra) {
  bool ok = !binary_ && fields_.size() == words.size() + extra;
  for (size_t i = 0; ok && i < words.size(); ++i) ok = fields_[i] == words[i];
  if (!ok) {
    std::string want;
    for (auto w : words) want += std::string(want.empty() ? "" : " ") + w;
    const std::string wanted = "expected '" + want + "' and " + std::to_string(extra);
    const std::string found = "found '" + std::string(kind()) + "' with " + std::to_string(size());
    malformed(line_, wanted + " field(s), " + found + " field(s)");
  }
  pos_ = words.size();
  return *this;
}

void LineReader::count(size_t k) {
  if (!binary_ && size() != k)
    malformed(line_, std::string(kind()) + " record: wrong number of fields");
}

std::string_view LineReader::word() {
  if (binary_) {
    const Field& f = field(Field::Word);
    return std::string_view(words_).substr(f.off, f.len);
  }
  if (pos_ >= size()) malformed(line_, std::string(kind()) + " record: too few fields");
  return fields_[pos_++];
}

int64_t LineReader::integer() { return binary_ ? field(Field::Int).z : parse_int(word(), line_); }

double LineReader::real() { return parse_real(word(), line_); }  // binary records have none

// ---- Format 3's binary records (FORMAT.md, "Format 3").

void LineReader::allow_binary(int n, int nv, int p) {
  allow_binary_ = true;
  n_ = n;
  nv_ = nv;
  p_ = p;
}

// The next field of the binary record read last, which the rules read in the order of its
// type's fields; the type is the format's, so a mismatch is the checker's own error.
const LineReader::Field& LineReader::field(Field::Type t) {
  if (pos_ >= bin_.size() || bin_[pos_].type != t)
    throw std::logic_error("check_cert: binary fields read out of order");
  return bin_[pos_++];
}

double LineReader::end(double a, double b, bool upper, int64_t offset, int bits) {
  if (!binary_) return real();
  const Field& f = field(Field::Code);
  if (f.raw) return f.x;
  const double x = std::fma(double(f.z + offset), std::ldexp(b - a, -bits), upper ? b : a);
  if (!std::isfinite(x)) malformed(line_, "a coded end is not finite");
  bin_[pos_ - 1].x = x;  // for --print
  bin_[pos_ - 1].raw = true;
  return x;
}

// The binary record read last as text: its kind and fields, an end not decoded (the check
// stopped before it) as '?'.
void LineReader::finish_print() {
  if (!print_ || !binary_ || printed_) return;
  printed_ = true;
  std::printf("%.*s", int(bin_kind_.size()), bin_kind_.data());
  for (const Field& f : bin_) {
    if (f.type == Field::Int) std::printf(" %lld", (long long)f.z);
    else if (f.type == Field::Word) std::printf(" %.*s", int(f.len), words_.data() + f.off);
    else if (f.raw) std::printf(" %a", f.x);
    else std::printf(" ?");
  }
  std::printf("\n");
}

int LineReader::byte() {
  const int c = std::getc(f_);
  if (c == EOF) malformed(line_, std::ferror(f_) ? kUnreadable : "unexpected end of file");
  bytes_read_ += char(c);
  return c;
}

// An unsigned LEB128 integer below 2^53, in at most 8 bytes (sums of two stay exact).
uint64_t LineReader::varint() {
  uint64_t x = 0;
  for (int shift = 0; shift < 56; shift += 7) {
    const int c = byte();
    x |= uint64_t(c & 0x7f) << shift;
    if (!(c & 0x80)) {
      if (x >= (uint64_t(1) << 53)) break;
      return x;
    }
  }
  malformed(line_, "binary integer out of range");
}

void LineReader::add(Field::Type t, int64_t i) {
  Field f{t};
  f.z = i;
  bin_.push_back(f);
}

void LineReader::word(std::string w) {
  Field f{Field::Word};
  f.off = uint32_t(words_.size());
  f.len = uint32_t(w.size());
  words_ += w;
  bin_.push_back(f);
}

// A coded end: 0 then 8 bytes (the double, little-endian), or 1 + the zigzag code of z.
void LineReader::code() {
  Field f{Field::Code};
  const uint64_t c = varint();
  if (c == 0) {
    uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= uint64_t(byte()) << (8 * i);
    f.raw = true;
    std::memcpy(&f.x, &bits, sizeof f.x);
    if (!std::isfinite(f.x)) malformed(line_, "a binary real is not finite");
  } else {
    f.z = (c - 1) & 1 ? -int64_t((c - 1) >> 1) - 1 : int64_t((c - 1) >> 1);
  }
  bin_.push_back(f);
}

void LineReader::decode(int tag) {
  bin_.clear();
  words_.clear();
  // A sum of steps (ids, link ends) stays far from int64's end: a larger one names no box.
  const auto step = [&](int64_t& sum, uint64_t by) {
    sum += int64_t(by);
    if (sum >= (int64_t(1) << 53)) malformed(line_, "binary id out of range");
    return sum;
  };
  // k characters of two bits each, four a byte: 0 '0', 1 '+', 2 '-' (3 and stray bits '?').
  const auto packed = [&](int k) {
    std::string s;
    for (int i = 0; i < k; i += 4) {
      int b = byte();
      for (int j = 0; j < 4 && i + j < k; ++j, b >>= 2) s += "0+-?"[b & 3];
      if (b) s += '?';  // bits after the k-th character
    }
    return s;
  };
  if (tag < 0xC0) {  // P or B, the variable in the tag (31: 31 + a varint)
    const bool P = tag < 0xA0;
    bin_kind_ = P ? "P" : "B";
    const uint64_t v = uint64_t(tag & 0x1f);
    add(Field::Int, int64_t(v == 31 ? 31 + varint() : v));
    code();
    if (P) code();
    return;
  }
  static const char* const kinds[] = {"X", "U", "N", "S", "K", "csnc"};
  if (tag > 0xC5)
    malformed(line_, "unknown binary record (first byte " + std::to_string(tag) + ")");
  bin_kind_ = kinds[tag - 0xC0];
  if (tag == 0xC0) {  // X: 0 hs, 1 + 2i eq<i>, 2 + 2k c<k>
    const uint64_t h = varint();
    word(h == 0       ? "hs"
         : h % 2 ? "eq" + std::to_string((h - 1) / 2)
                 : "c" + std::to_string((h - 2) / 2));
  } else if (tag <= 0xC3) {  // U, N, S: the id is the next one; the signs
    add(Field::Int, step(last_id_, 1));
    word(p_ == 0 ? "." : packed(p_));
    if (tag == 0xC3)
      for (int k = 0; k < 6 * n_; ++k) code();  // Q~, IMAGE, then DX and DQ
  } else if (tag == 0xC4) {  // K: A as a step from the last A, B - A - 1, SHIFT, ends
    add(Field::Int, step(last_a_, varint()));
    int64_t b = last_a_;
    add(Field::Int, step(b, 1 + varint()));
    word(packed(nv_));
    for (int k = 0; k < 3 * n_; ++k) code();  // the witness, then Q~
  } else {  // csnc: K, SIZE, then each id as a step beyond the one before
    add(Field::Int, int64_t(varint()));
    const int64_t size = int64_t(varint());
    add(Field::Int, size);
    for (int64_t i = 0, id = -1; i < size; ++i) add(Field::Int, step(id, 1 + varint()));
  }
}

std::vector<double> LineReader::reals(size_t k) {
  std::vector<double> out(k);
  for (double& x : out) x = real();
  return out;
}

std::vector<double> LineReader::intervals(size_t k) {
  std::vector<double> out = reals(2 * k);
  for (size_t j = 0; j < k; ++j)
    if (!(out[2 * j] <= out[2 * j + 1])) malformed(line_, "interval with LO > HI");
  return out;
}

}  // namespace cc
