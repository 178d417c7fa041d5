#include "solve_resume.h"

#include <signal.h>

#include <cerrno>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "aspects_version.h"

namespace aspects {

namespace {

std::string show(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

template <class T>
void adopt(const SolveOptions& o, const char* name, T& value, const T& saved,
           const std::string& value_text, const std::string& saved_text) {
  if (o.was_given(name) && !(value == saved))
    throw CheckpointError("--resume: " + std::string(name) + " " + value_text +
                          " differs from the checkpoint's " + saved_text +
                          " (give the same value, or leave the option out)");
  value = saved;
}

// Whether process `pid` may still write its temporaries: not when it does not exist, nor
// when it has ended and its parent has not collected it yet (a zombie: the rank 0 of a
// job mpirun has just ended), which a signal 0 does not tell.
bool may_still_write(long pid) {
  if (kill(pid_t(pid), 0) != 0 && errno == ESRCH) return false;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return true;  // not ours to judge
  const size_t paren = line.rfind(')');  // the state follows the command's name
  return paren == std::string::npos || paren + 2 >= line.size() ||
         (line[paren + 2] != 'Z' && line[paren + 2] != 'X');
}

}  // namespace

void adopt_checkpoint(SolveOptions& o, const CheckpointHeader& h) {
  if (h.version != ASPECTS_VERSION_FULL)
    throw CheckpointError("--resume: the checkpoint was written by aspects " + h.version +
                          ", this is aspects " ASPECTS_VERSION_FULL
                          ": a state is resumed only by the program that wrote it");
  adopt(o, "--eps", o.eps, h.eps, show(o.eps), show(h.eps));
  long prec = long(h.precision);
  adopt(o, "--prec", o.prec, prec, std::to_string(o.prec), std::to_string(prec));
  adopt(o, "--tau", o.tau, h.tau, show(o.tau), show(h.tau));
  adopt(o, "--bisect", o.bisect, h.bisect, o.bisect, h.bisect);
  auto flag = [](bool b) { return std::string(b ? "given" : "not given"); };
  bool all_links = h.all_links, no_cert = h.no_cert;
  adopt(o, "--all-links", o.all_links, all_links, flag(o.all_links), flag(all_links));
  adopt(o, "--no-cert", o.no_cert, no_cert, flag(o.no_cert), flag(no_cert));
  int format = h.cert_format;
  adopt(o, "--cert-format", o.cert_format, format, std::to_string(o.cert_format),
        std::to_string(format));
  namespace fs = std::filesystem;
  if (o.was_given("--out") && fs::weakly_canonical(o.out_dir) != fs::weakly_canonical(o.resume_dir))
    throw UsageError("--out " + o.out_dir + " differs from --resume " + o.resume_dir +
                     " (a resumed run writes where it was stopped)");
  o.out_dir = o.resume_dir;
  if (!o.was_given("--checkpoint")) o.checkpoint = h.checkpoint_seconds;
  if (!o.was_given("MODEL")) o.model_path = h.model_file;
}

int remove_stale_temporaries(const std::string& dir) {
  namespace fs = std::filesystem;
  int removed = 0;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    size_t at = name.find(".tmp.");
    if (at == std::string::npos) continue;
    const std::string base = name.substr(0, at);
    if (base != "aspects.cert" && base != "aspects.cert.zst" && base != kCheckpointName &&
        base != "boxes.csv" && base != "summary.json" && base != "aspects.idx")
      continue;
    char* end = nullptr;
    long pid = std::strtol(name.c_str() + at + 5, &end, 10);
    if (pid <= 0 || end == name.c_str() + at + 5) continue;
    if (may_still_write(pid)) continue;
    removed += fs::remove(entry.path(), ec) ? 1 : 0;
  }
  return removed;
}

std::unique_ptr<Checkpoint> open_resumed_run(SolveOptions& o) {
  if (o.resume_dir.empty()) return nullptr;
  auto resumed =
      std::make_unique<Checkpoint>(read_checkpoint(o.resume_dir + "/" + kCheckpointName));
  adopt_checkpoint(o, resumed->header);
  remove_stale_temporaries(o.out_dir);  // a killed run's
  return resumed;
}

void resume_search(Checkpoint& resumed, CertificateWriter* cert, AspectsConfig& cfg) {
  SearchState& st = resumed.state;
  if (cert && st.top_done) {
    std::vector<TreeRecordFile::Mark> marks;
    for (const auto& [offset, task] : resumed.top_marks) marks.push_back({long(offset), task});
    cert->restore(-1, resumed.top_records, std::move(marks));
    for (size_t k = 0; k < st.deferred.size(); ++k)
      if (st.done[k]) cert->restore(int32_t(k), resumed.records[k]);
  }
  cfg.resume = &st;
  // Its subtrees were cut at the checkpoint's depth (a distributed run's depends on P):
  // the checkpoints this run writes say so.
  if (st.top_done) cfg.defer_depth = resumed.header.defer_depth;
}

Model resumed_model(const SolveOptions& o, const CheckpointHeader& h) {
  if (!o.was_given("MODEL"))
    return parse_model(h.model_text, h.model_file.empty() ? "(embedded RRRRR)" : h.model_file);
  Model m = load_model(o.model_path);
  if (sha256_hex(m.source) != h.model_sha256)
    throw CheckpointError("--resume: " + o.model_path +
                          " is not the model the checkpoint was made for (its text differs; "
                          "leave MODEL out to use the checkpoint's)");
  return m;
}

}  // namespace aspects
