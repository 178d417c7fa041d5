#include "distribution/mpi_resume.h"

#include "distribution/mpi_message.h"

namespace aspects {

namespace {

constexpr int kResumedRun = 12;

// u8 ok; when 1: f64 eps  i64 prec  f64 tau  str bisect  u8 all_links  u8 no_cert
//               u8 cert_format  str model_text  str model_name
std::string run_message(const SolveOptions& o, const ResumedModel* model) {
  MessageWriter w;
  w.u8(model != nullptr);
  if (!model) return w.s;
  w.f64(o.eps);
  w.i64(o.prec);
  w.f64(o.tau);
  w.str(o.bisect);
  w.u8(o.all_links);
  w.u8(o.no_cert);
  w.u8(uint8_t(o.cert_format));
  w.str(model->text);
  w.str(model->name);
  return w.s;
}

}  // namespace

bool rank0_resumes(MpiJob& job, const SolveOptions& o) {
  return job.broadcast({o.resume_dir.empty() ? 0 : 1})[0] != 0;
}

std::optional<ResumedModel> share_resumed_run(MpiJob& job, SolveOptions& o,
                                              const ResumedModel* model) {
  if (job.rank() == 0) {
    const std::string msg = run_message(o, model);
    for (int r = 1; r < job.size(); ++r) job.send(r, kResumedRun, msg);
    return std::nullopt;
  }
  const std::string msg = job.receive(0, kResumedRun);
  MessageReader in(msg, 0);
  if (!in.u8()) return std::nullopt;
  o.eps = in.f64_bits();
  o.prec = long(in.i64());
  o.tau = in.f64_bits();
  o.bisect = in.str();
  o.all_links = in.u8();
  o.no_cert = in.u8();
  o.cert_format = in.u8();
  ResumedModel m;
  m.text = in.str();
  m.name = in.str();
  if (!in.at_end()) in.fail("trailing bytes");
  // Where rank 0 writes; this rank writes nothing, but --checkpoint needs a directory.
  if (o.out_dir.empty()) o.out_dir = o.resume_dir.empty() ? "." : o.resume_dir;
  return m;
}

}  // namespace aspects
