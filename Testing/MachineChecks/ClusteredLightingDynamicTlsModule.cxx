// SPDX-License-Identifier: BSD-3-Clause
// Sanitizer builds only: a loadable module with one small thread_local block, for
// ClusteredLightingDynamicTlsCheck. Like Mesa's GL libraries, which are loaded with
// dlopen too, its thread_local data lives in dynamic TLS blocks that glibc mallocs per
// thread, on first use, through __tls_get_addr.
extern "C"
{
  __attribute__((visibility("default"))) char* ClusteredLightingTouchDynamicTls();
}

namespace
{
thread_local char Block[40];
}

char* ClusteredLightingTouchDynamicTls()
{
  Block[0] = 1;
  return Block;
}
