// Private to the picture writers: cairo's stream output into a string.
#pragma once

#include <cairo.h>

#include <string>

namespace datomsim::render::detail {

// A cairo write function that appends to the std::string given as its closure.
inline cairo_status_t appendToString(void* closure, const unsigned char* data,
                                     unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace datomsim::render::detail
