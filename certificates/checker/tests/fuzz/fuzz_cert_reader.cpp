// fuzz_cert_reader.cpp — libFuzzer target: the whole check of check_cert (reader, model
// parser, proofs, graph) on arbitrary bytes, read through fmemopen. Built by build_fuzz.sh
// from the checker's sources without cli.cpp; any crash, leak, sanitizer report or hang is a bug. Mutations
// of the model text almost never keep `model BYTES SHA256` right, so when the input has
// that record and an `end-model` line, the harness first makes it consistent: the parser
// and the proofs then see mutated models too.
#include "../../checker.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string s(reinterpret_cast<const char*>(data), size);
  size_t a = s.find("\nmodel "), b = s.find('\n', a + 1), e = s.find("\nend-model\n", b);
  if (a != std::string::npos && b != std::string::npos && e != std::string::npos) {
    std::string text = s.substr(b + 1, e - b - 1);
    const std::string record = "model " + std::to_string(text.size()) + " " + cc::sha256_hex(text);
    s = s.substr(0, a + 1) + record + s.substr(b);
  }
  FILE* f = s.empty() ? nullptr : fmemopen(&s[0], s.size(), "rb");
  cc::CheckOptions o;
  o.quiet = true;
  if (f) cc::check_certificate(f, o);
  return 0;
}
