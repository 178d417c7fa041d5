#include "results/result_files.h"

#include <zstd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>

#include "results/sha256.h"

namespace aspects {

namespace {

constexpr size_t kHeaderBytes = 4096;  // the first three lines are far shorter

// The first bytes of the file as written, decompressed when it is a zstd frame.
std::string header_bytes(const std::string& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) return "";
  std::string raw(kHeaderBytes, '\0');
  raw.resize(std::fread(&raw[0], 1, raw.size(), f.get()));
  const bool zstd = raw.size() >= 4 && static_cast<unsigned char>(raw[0]) == 0x28 &&
                    static_cast<unsigned char>(raw[1]) == 0xB5 &&
                    static_cast<unsigned char>(raw[2]) == 0x2F &&
                    static_cast<unsigned char>(raw[3]) == 0xFD;
  if (!zstd) return raw;
  std::unique_ptr<ZSTD_DCtx, size_t (*)(ZSTD_DCtx*)> z(ZSTD_createDCtx(), &ZSTD_freeDCtx);
  std::string text(kHeaderBytes, '\0');
  ZSTD_outBuffer out{&text[0], text.size(), 0};
  std::string chunk = raw;
  // Fed until the output buffer is full or the file ends: the start is enough.
  while (!chunk.empty() && out.pos < out.size) {
    ZSTD_inBuffer in{chunk.data(), chunk.size(), 0};
    while (in.pos < in.size && out.pos < out.size)
      if (ZSTD_isError(ZSTD_decompressStream(z.get(), &out, &in))) return "";
    chunk.assign(kHeaderBytes, '\0');
    chunk.resize(std::fread(&chunk[0], 1, chunk.size(), f.get()));
  }
  text.resize(out.pos);
  return text;
}

std::string summary_field(const nlohmann::json& s, const char* key) {
  const auto it = s.find(key);
  if (it == s.end() || it->is_null()) return "";
  return it->is_string() ? it->get<std::string>() : std::string("?");
}

}  // namespace

std::string short_hash(const std::string& hex) {
  return hex.empty() ? std::string("(none)") : hex.substr(0, 16);
}

std::string certificate_model_sha256(const std::string& path) {
  const std::string text = header_bytes(path);
  size_t at = 0;
  for (int line = 0; line < 2; ++line) {
    at = text.find('\n', at);
    if (at == std::string::npos) return "";
    ++at;
  }
  const size_t end = text.find('\n', at);
  if (end == std::string::npos) return "";
  const std::string line = text.substr(at, end - at);  // "model BYTES SHA256"
  const size_t space = line.rfind(' ');
  if (line.compare(0, 6, "model ") != 0 || space == std::string::npos) return "";
  const std::string hash = line.substr(space + 1);
  return hash.size() == 64 ? hash : "";
}

std::vector<std::string> mismatched_files(const std::string& dir, const ResultIndex& idx) {
  namespace fs = std::filesystem;
  std::vector<std::string> bad;
  const std::string model_sha = sha256_hex_of(idx.model_source);
  for (const char* name : {kCertificateName, kCompressedCertificateName}) {
    const std::string path = dir + "/" + name;
    std::error_code ec;
    if (!fs::exists(path, ec)) continue;
    if (idx.certificate_file != name) {
      bad.push_back(path + ": a certificate of another run: " + kResultIndexName + " records " +
                    (idx.certificate_file.empty() ? std::string("none (solved with --no-cert)")
                                                  : idx.certificate_file) +
                    " (remove it, or solve again)");
      continue;
    }
    const std::string cert_model = certificate_model_sha256(path);
    if (cert_model.empty())
      bad.push_back(path + ": no model line could be read (unreadable, or not a certificate)");
    else if (cert_model != model_sha)
      bad.push_back(path + ": its model (sha256 " + short_hash(cert_model) +
                    ") is not the result's (sha256 " + short_hash(model_sha) + ", the model in " +
                    kResultIndexName + "): a certificate of another run (solve again)");
  }
  const std::string summary_path = dir + "/" + kSummaryName;
  std::ifstream in(summary_path);
  if (!in) return bad;
  nlohmann::json s;
  try {
    s = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    bad.push_back(summary_path + ": not JSON (damaged; solve again)");
    return bad;
  }
  if (!s.is_object() || !s.contains("index_sha256")) {
    bad.push_back(summary_path + ": records no index_sha256 (written by an older aspects, or "
                  "not a summary; solve again)");
    return bad;
  }
  const struct {
    const char* key;
    const std::string& want;
    const char* what;
  } fields[] = {{"index_sha256", idx.sha256, "the index's"},
                {"certificate_sha256", idx.certificate_sha256, "the index records"},
                {"model_sha256", model_sha, "the index's model's"}};
  for (const auto& f : fields) {
    const std::string got = summary_field(s, f.key);
    if (got != f.want)
      bad.push_back(summary_path + ": not of the run that wrote " + kResultIndexName + ": its " +
                    f.key + " is " + short_hash(got) + ", " + f.what + " " + short_hash(f.want) +
                    " (files of two runs; solve again)");
  }
  return bad;
}

}  // namespace aspects
