#include "verify_command.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "results/result_files.h"
#include "results/result_index.h"
#include "results/sha256.h"
#include "results/usage_error.h"  // UsageError

extern char** environ;

namespace aspects {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// check_cert: $ASPECTS_CHECK_CERT, the one beside this program (installed), the build
// tree's (apps/../certificates/), else the one on PATH (as Result.check() looks).
std::string find_check_cert() {
  if (const char* env = std::getenv("ASPECTS_CHECK_CERT"); env && *env) return env;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec)
    for (const fs::path& p : {self.parent_path() / "check_cert",
                              self.parent_path().parent_path() / "certificates" / "check_cert"})
      if (access(p.c_str(), X_OK) == 0) return p.string();
  return "check_cert";  // posix_spawnp searches PATH
}

// Runs check_cert --json on `cert` (its statistics go to our stderr); its one JSON line.
json run_check_cert(const std::string& cert, int threads) {
  const std::string program = find_check_cert();
  std::vector<std::string> args = {program, "--json"};
  if (threads > 0) args.insert(args.end(), {"--threads", std::to_string(threads)});
  args.push_back(cert);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int out[2];
  if (pipe(out) != 0) throw std::runtime_error("cannot run check_cert: no pipe");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, out[0]);
  pid_t pid;
  const int rc = posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(out[1]);
  std::string text;
  char buf[4096];
  for (ssize_t n; (n = read(out[0], buf, sizeof buf)) > 0;) text.append(buf, size_t(n));
  close(out[0]);
  if (rc != 0)
    throw UsageError("check_cert not found (build it, install it beside aspects, or set "
                     "ASPECTS_CHECK_CERT)");
  int status = 0;
  waitpid(pid, &status, 0);
  try {
    return json::parse(text);
  } catch (const json::exception&) {
    throw std::runtime_error(program + " gave no verdict (exit " +
                             std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
  }
}

// One file's finding: what it rests on and what was found.
struct Finding {
  std::string file;
  bool ok = true;
  std::string said;                   // the line printed after the file's name
  std::vector<std::string> problems;  // mismatches
};

long number(const json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<long>() : -1;
}

template <class T>
void compare(Finding& f, const char* what, const T& got, const T& want) {
  if (!(got == want))
    f.problems.push_back(std::string(what) + " " + json(got).dump() + ", the certificate's " +
                         json(want).dump());
}

Finding check_index(const ResultIndex& idx, const json& cc) {
  Finding f;
  f.file = kResultIndexName;
  compare(f, "certificate sha256", idx.certificate_sha256, cc.value("sha256_cert", ""));
  compare(f, "model sha256", sha256_hex_of(idx.model_source), cc.value("sha256_model", ""));
  compare(f, "eps", idx.eps, cc.value("eps", 0.0));
  compare(f, "solution boxes", long(idx.solutions.size()), number(cc, "solutions"));
  compare(f, "undecided boxes", long(idx.undecided.size()),
          number(cc, "undecided") + number(cc, "unexplored"));
  compare(f, "links", long(idx.links.size()), number(cc, "links"));
  compare(f, "CSNCs", long(idx.csnc_count), number(cc, "csncs"));
  f.ok = f.problems.empty();
  f.said = f.ok ? "matches: records this certificate's sha256 and its model; its checksum "
                  "holds; " + std::to_string(idx.solutions.size()) + " solution boxes, " +
                      std::to_string(idx.undecided.size()) + " undecided, " +
                      std::to_string(idx.links.size()) + " links, " +
                      std::to_string(idx.csnc_count) + " CSNCs, as the certificate"
                : "MISMATCH";
  return f;
}

Finding check_summary(const std::string& path, const ResultIndex& idx, const json& cc) {
  Finding f;
  f.file = kSummaryName;
  std::ifstream in(path);
  if (!in) {
    f.said = "absent: nothing to compare";
    return f;
  }
  json s;
  try {
    s = json::parse(in);
  } catch (const json::exception&) {
    f.ok = false;
    f.said = "MISMATCH";
    f.problems.push_back("not JSON");
    return f;
  }
  auto str = [&](const char* key) {
    return s.contains(key) && s[key].is_string() ? s[key].get<std::string>() : std::string();
  };
  auto num = [&](const char* a, const char* b) {
    return s.contains(a) && s[a].contains(b) && s[a][b].is_number() ? s[a][b].get<long>() : -1;
  };
  compare(f, "certificate_sha256", str("certificate_sha256"), cc.value("sha256_cert", ""));
  compare(f, "model_sha256", str("model_sha256"), cc.value("sha256_model", ""));
  if (str("index_sha256") != idx.sha256)
    f.problems.push_back("index_sha256 " + json(str("index_sha256")).dump() + ", " +
                         kResultIndexName + "'s " + json(idx.sha256).dump());
  compare(f, "eps", s.value("eps", 0.0), cc.value("eps", 0.0));
  // A run stopped after its search is partial (complete false) with a whole tree
  // (check_cert's complete=yes); complete the other way round is a claim too many.
  if (s.value("complete", false) && !cc.value("complete", false))
    f.problems.push_back("complete true, the certificate's complete=no");
  compare(f, "separated_lower_bound", num("csncs", "separated_lower_bound"),
          number(cc, "lower_bound"));
  compare(f, "solution boxes", num("boxes", "solution"), number(cc, "solutions"));
  compare(f, "certified links", num("links", "certified"), number(cc, "links"));
  compare(f, "CSNCs", num("csncs", "count"), number(cc, "csncs"));
  f.ok = f.problems.empty();
  f.said = f.ok ? "matches: records this certificate's sha256, its model's and the index's; "
                  "lower bound " + std::to_string(number(cc, "lower_bound")) +
                      " and the counts as the certificate, complete only if it is"
                : "MISMATCH";
  return f;
}

const char* outcome_name(VerifyOutcome o) {
  switch (o) {
    case VerifyOutcome::Verified: return "VERIFIED";
    case VerifyOutcome::Unchecked: return "UNCHECKED";
    case VerifyOutcome::NotVerified: return "NOT VERIFIED";
  }
  return "?";
}

void print_text(const std::string& cert_name, const json& cc, const std::vector<Finding>& files,
                VerifyOutcome outcome) {
  const std::string verdict = cc.value("verdict", "?");
  std::printf("%-17s check_cert %s", cert_name.c_str(), verdict.c_str());
  if (cc.contains("sha256_cert"))
    std::printf(": sha256 %s, model sha256 %s, %s, lower bound %ld\n",
                cc["sha256_cert"].get<std::string>().c_str(),
                cc["sha256_model"].get<std::string>().c_str(),
                cc.value("complete", false) ? "complete" : "partial (complete=no)",
                number(cc, "lower_bound"));
  else
    std::printf(": %s\n", cc.value("reason", std::string("no reason given")).c_str());
  for (const Finding& f : files) {
    std::printf("%-17s %s\n", f.file.c_str(), f.said.c_str());
    for (const std::string& p : f.problems) std::printf("  %s\n", p.c_str());
  }
  switch (outcome) {
    case VerifyOutcome::Verified:
    case VerifyOutcome::Unchecked:
      std::printf("%s: check_cert %s the certificate; the index and the summary are tied to "
                  "it by hashes and counts (their boxes, signs and witnesses are not compared "
                  "with the certificate's records)\n",
                  outcome_name(outcome),
                  outcome == VerifyOutcome::Verified
                      ? "verified"
                      : "verified all but the bound (a user factor) of");
      break;
    case VerifyOutcome::NotVerified:
      std::printf("NOT VERIFIED: %s\n",
                  verdict == "VERIFIED" || verdict == "UNCHECKED"
                      ? "a file of the directory does not match the certificate"
                      : "check_cert did not accept the certificate");
      break;
  }
}

}  // namespace

int run_verify(const VerifyOptions& opts) {
  const std::string& dir = opts.result_dir;
  // Missing is an input error; present but damaged or edited is a finding (exit 1).
  if (dir.find('\0') != std::string::npos || !fs::is_directory(dir) ||
      !fs::exists(fs::path(dir) / kResultIndexName))
    (void)read_result_index(dir);  // throws the IndexError that says which
  ResultIndex idx;
  try {
    idx = read_result_index(dir);
  } catch (const IndexError& e) {
    if (opts.json)
      std::cout << json{{"verdict", "NOT VERIFIED"}, {"index", e.what()}}.dump() << '\n';
    else
      std::printf("%-17s REFUSED: %s\nNOT VERIFIED: the index cannot be trusted\n",
                  kResultIndexName, e.what());
    return 1;
  }
  if (idx.certificate_file.empty())
    throw UsageError(dir + ": the result has no certificate (solved with --no-cert): nothing "
                     "for check_cert to verify");
  const std::string cert = dir + "/" + idx.certificate_file;
  if (!fs::exists(cert))
    throw UsageError(cert + ": missing (the certificate " + kResultIndexName + " records)");
  const json cc = run_check_cert(cert, opts.threads);
  const std::string verdict = cc.value("verdict", "?");
  const bool accepted = verdict == "VERIFIED" || verdict == "UNCHECKED";

  std::vector<Finding> files;
  if (accepted) {
    files.push_back(check_index(idx, cc));
    files.push_back(check_summary(dir + "/" + kSummaryName, idx, cc));
    // A second certificate (another run's) beside this one.
    const std::string other = idx.certificate_file == kCertificateName
                                  ? kCompressedCertificateName
                                  : kCertificateName;
    if (fs::exists(fs::path(dir) / other))
      files.push_back({other, false, "MISMATCH",
                       {"a certificate of another run: " + std::string(kResultIndexName) +
                        " records " + idx.certificate_file}});
  }
  bool all_ok = accepted;
  for (const Finding& f : files) all_ok = all_ok && f.ok;
  const VerifyOutcome outcome = !all_ok               ? VerifyOutcome::NotVerified
                                : verdict == "VERIFIED" ? VerifyOutcome::Verified
                                                        : VerifyOutcome::Unchecked;
  if (opts.json) {
    json j = {{"verdict", outcome_name(outcome)}, {"certificate", idx.certificate_file},
              {"check_cert", cc}};
    for (const Finding& f : files)
      j["files"].push_back({{"file", f.file}, {"matches", f.ok}, {"problems", f.problems}});
    std::cout << j.dump() << '\n';
  } else {
    print_text(idx.certificate_file, cc, files, outcome);
  }
  switch (outcome) {
    case VerifyOutcome::Verified: return 0;
    case VerifyOutcome::Unchecked: return 3;
    case VerifyOutcome::NotVerified: return 1;
  }
  return 1;
}

}  // namespace aspects
