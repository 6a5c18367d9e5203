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
/// The machine, GL driver and command of the run.
void WriteMachine(vtkRenderWindow* rw, const std::string& command, const std::string& path);
/**
 * Checks a written CSV: well-formed rows, a frame time in every row, errors, counts and
 * memory in every clustered row, and every error budget met. Returns 0 when all hold.
 */
int CheckCSV(const std::string& path);
} // namespace ClusteredLightingBenchmark

#endif
