// What the shared library exports: the public API only. Everything else is hidden, so that a
// program built against the installed package links to nothing but this API.
#pragma once

#if defined(_WIN32)
#define DATOMSIM_API
#else
#define DATOMSIM_API __attribute__((visibility("default")))
#endif
