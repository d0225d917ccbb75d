#pragma once
/// @file
/// Stopping the BLAS library's idle threads, which compete with tailor's own.

namespace tailor::cli {

/// Joins the thread pool OpenBLAS starts when it is loaded, if OpenBLAS is the process's
/// BLAS (Debian's default provider of the `libblas.so.3` that CHOLMOD links); otherwise
/// does nothing. Each of OpenBLAS's threads spins in `sched_yield` for about 2^28 cycles
/// (~0.1 s) after it starts before it sleeps: on a 2-core machine that is one core taken
/// from the first 0.1 s of every command (measured: `tailor detect` on cloth-ball builds
/// its detector in 121 ms instead of 75). tailor calls no threaded BLAS routine; should
/// CHOLMOD ever call one, OpenBLAS starts its pool again on that first call.
void stop_idle_blas_threads();

}  // namespace tailor::cli
