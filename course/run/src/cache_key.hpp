#pragma once
// The name the controller cache gives a compile.

#include <openssl/evp.h>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

namespace frob::course {

// What the cache knows a compile by: SHA-256 of its fields, each after its length, so that no two
// different compiles share a module (a 64-bit FNV could be made to collide in minutes: a file that
// does nothing graded with another's module).
class CacheKey {
 public:
  CacheKey() : ctx_(EVP_MD_CTX_new(), EVP_MD_CTX_free) { EVP_DigestInit_ex(ctx_.get(), EVP_sha256(), nullptr); }
  CacheKey& add(std::string_view field) {
    const std::uint64_t size = field.size();
    EVP_DigestUpdate(ctx_.get(), &size, sizeof size);
    EVP_DigestUpdate(ctx_.get(), field.data(), field.size());
    return *this;
  }
  // The first 128 bits in hex: a module's name.
  [[nodiscard]] std::string hex() {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    EVP_DigestFinal_ex(ctx_.get(), digest, &length);
    char out[33] = {};
    for (unsigned int i = 0; i < 16 && i < length; ++i) std::snprintf(out + 2 * i, 3, "%02x", digest[i]);
    return out;
  }

 private:
  std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> ctx_;
};

}  // namespace frob::course
