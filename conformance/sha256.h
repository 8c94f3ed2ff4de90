// SHA-256 of a byte stream, hex: the suite's signature hash (OpenSSL's EVP, libssl-dev).
#pragma once

#include <memory>
#include <string>
#include <string_view>

namespace zb::conformance {

class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;

  void update(std::string_view bytes);
  std::string hex();  // 64 lower-case digits; ends the hash

 private:
  struct Context;
  std::unique_ptr<Context> ctx_;
};

std::string sha256_hex(std::string_view bytes);

}  // namespace zb::conformance
