// SPDX-License-Identifier: BSD-3-Clause
// Sanitizer builds only (scripts/check-machine.sh): the leak check at exit
// must survive threads that use dynamic TLS, as llvmpipe's threads do.
//
// GCC 12's __tls_get_addr interceptor takes a dynamic TLS block that starts 16 bytes into
// a page for a block of glibc older than 2.25, which had a 16-byte header there, and
// reads the block's address and size from the two words before it. Today's glibc has no
// such header: those words belong to the allocator, the range is bogus, and
// LeakSanitizer's tracer dies scanning it ("Tracer caught signal 11", "LeakSanitizer has
// encountered a fatal error"; google/sanitizers#1322). That most likely failed
// TestClusteredLightingBadInput in CI, where malloc happened to put one of Mesa's blocks
// at such an address. Here ASan's allocator puts the 40-byte block of
// ClusteredLightingDynamicTlsModule at page offset 16 in every thread (64 of 64, in every
// run), so the crash is certain unless scripts/run-sanitizers.sh turns the interceptor
// off (intercept_tls_get_addr=0).
//
// Usage: ClusteredLightingDynamicTlsCheck <module>
// Exit code 0: blocks were at page offset 16 and the leak check ran to its end.
// Exit code 1: the module could not be loaded, or no block was at page offset 16 (the
// check would prove nothing; the block's size needs revisiting for this allocator).
#include <dlfcn.h> // for dlopen

#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <thread>

namespace
{
using TouchFunction = char* (*)();

std::mutex Mutex;
std::condition_variable Ready;
int Started = 0;
int AtPageOffset16 = 0;

// Touches the module's thread_local block, then waits forever: the thread is still alive,
// with its dynamic TLS, when the leak check runs at exit.
void Run(TouchFunction touch)
{
  const char* block = touch();
  std::unique_lock<std::mutex> lock(Mutex);
  AtPageOffset16 += reinterpret_cast<std::uintptr_t>(block) % 4096 == 16 ? 1 : 0;
  ++Started;
  Ready.notify_all();
  std::condition_variable never;
  never.wait(lock, [] { return false; });
}
}

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::printf("usage: %s <module>\n", argv[0]);
    return 1;
  }
  void* module = dlopen(argv[1], RTLD_NOW);
  auto touch = module
    ? reinterpret_cast<TouchFunction>(dlsym(module, "ClusteredLightingTouchDynamicTls"))
    : nullptr;
  if (!touch)
  {
    std::printf("cannot load %s: %s\n", argv[1], dlerror());
    return 1;
  }
  const int numberOfThreads = 64;
  for (int i = 0; i < numberOfThreads; ++i)
  {
    std::thread(Run, touch).detach();
  }
  std::unique_lock<std::mutex> lock(Mutex);
  Ready.wait(lock, [] { return Started == numberOfThreads; });
  std::printf(
    "%d live threads, %d dynamic TLS blocks at page offset 16\n", numberOfThreads, AtPageOffset16);
  std::fflush(stdout);
  // The leak check runs after main returns, with the threads still waiting.
  return AtPageOffset16 > 0 ? 0 : 1;
}
