// Base64 (RFC 4648, with padding): images inside HTML pages and JSON as data URLs. Written here
// rather than taken from a library: a dozen lines, and no Debian package the framework already
// links offers it (OpenSSL's EVP_EncodeBlock would add a dependency for it alone).
#pragma once

#include <string>
#include <string_view>

namespace rt {

std::string base64(std::string_view data);

}  // namespace rt
