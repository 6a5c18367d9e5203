// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file BenchmarkReport.h
 * @brief What the benchmark writes: results.csv, results.md, pareto.png, scaling.png,
 * machine.txt, and the check of a written CSV (--check, ctest Benchmark.Quick).
 */
#ifndef BenchmarkReport_h
#define BenchmarkReport_h

#include "BenchmarkMeasure.h"

#include <string>
#include <vector>

class vtkRenderWindow;

namespace ClusteredLightingBenchmark
{
/// Every row, one line each (the columns of CSVHeader).
void WriteCSV(const std::vector<Row>& rows, const std::string& path);
/// The same as a Markdown table.
void WriteMarkdown(const std::vector<Row>& rows, const std::string& path);
/// pareto.png (image error against frame time, bunny, 4,096 uniform lights, with the
/// Pareto front) and scaling.png (frame time against light count).
void WritePlots(const std::vector<Row>& rows, const std::string& dir);
/**
 * How fast this host is right now, on one thread, in two numbers: arithmetic (chains of
 * multiply-adds, Gflop/s) and memory (copies of a 256 MiB buffer, GB/s), each the best of
 * 3 tries. The benchmark's machine is a virtual machine whose host CPU changes: the same
 * rows on a host without AVX-512 (2026-11-27) took 2x as long for the clustered and stock
 * frames as on one with it (2026-11-26), and 1.5x for brute force (docs/benchmark).
 * Probed at the start and the end of a run and written to machine.txt, so that runs on
 * different hosts can be told apart.
 */
std::string ProbeHost();
/// The machine, GL driver and command of the run, and the host probes taken around it.
void WriteMachine(vtkRenderWindow* rw, const std::string& command, const std::string& path,
  const std::string& probeAtStart = std::string(), const std::string& probeAtEnd = std::string());
/**
 * Checks a written CSV: well-formed rows, a frame time in every row, errors, counts and
 * memory in every clustered row, and every error budget met. Returns 0 when all hold.
 */
int CheckCSV(const std::string& path);
} // namespace ClusteredLightingBenchmark

#endif
