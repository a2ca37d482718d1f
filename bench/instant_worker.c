// SPDX-License-Identifier: GPL-3.0-or-later
/* A worker that answers at once, for bench/orchestrator_scale.sh: the
 * converged result of tests/fixtures/fake_worker.sh's "ok" mode
 * (dp_star = 1159 + Δ*, Δ* = (Lx Ly Lz / N)^(1/3) from the job's
 * case.domain_dp and grid.cells) in one small process, so the benchmark
 * measures the orchestrator at rates the shell fake (a few processes per
 * job, about 0.2 s of a slot) cannot reach.
 *
 *   instant_worker solve JOB.json -o RESULT.json [ignored options]
 *   instant_worker --version
 *
 * INSTANT_WORKER_LOG=FILE: each solve appends its RESULT path to FILE (one
 * write of one line, O_APPEND), so bench/stop_latency.sh can count how
 * often each job ran.
 */
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The n numbers of the array after "key" in text; 0 when not found. */
static int numbers_after(const char* text, const char* key, double* out, int n) {
  const char* p = strstr(text, key);
  if (!p) return 0;
  p = strchr(p, '[');
  if (!p) return 0;
  ++p;
  for (int i = 0; i < n; ++i) {
    char* end = NULL;
    out[i] = strtod(p, &end);
    if (end == p) return 0;
    p = end;
    while (*p == ' ' || *p == ',' || *p == '\n' || *p == '\t' || *p == '\r') ++p;
  }
  return 1;
}

/* Appends "result\n" to $INSTANT_WORKER_LOG when it is set. */
static int log_invocation(const char* result) {
  const char* log = getenv("INSTANT_WORKER_LOG");
  if (!log || !*log) return 0;
  char line[4096];
  const int n = snprintf(line, sizeof line, "%s\n", result);
  const int fd = open(log, O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd < 0 || n <= 0 || n >= (int)sizeof line || write(fd, line, (size_t)n) != n) {
    perror(log);
    return 1;
  }
  return close(fd) == 0 ? 0 : 1;
}

int main(int argc, char** argv) {
  if (argc > 1 && strcmp(argv[1], "--version") == 0) {
    puts("gridfree 0.0.0 (instant bench worker)");
    return 0;
  }
  if (argc < 3 || strcmp(argv[1], "solve") != 0) {
    fputs("usage: instant_worker solve JOB -o RESULT\n", stderr);
    return 1;
  }
  const char* result = NULL;
  for (int i = 3; i + 1 < argc; ++i)
    if (strcmp(argv[i], "-o") == 0) result = argv[i + 1];
  if (!result) {
    fputs("no -o\n", stderr);
    return 1;
  }
  FILE* in = fopen(argv[2], "rb");
  if (!in) {
    perror(argv[2]);
    return 1;
  }
  static char text[1 << 20];
  const size_t len = fread(text, 1, sizeof text - 1, in);
  fclose(in);
  text[len] = '\0';
  double cells[3], domain[3];
  if (!numbers_after(text, "\"cells\"", cells, 3) || !numbers_after(text, "\"domain_dp\"", domain, 3)) {
    fputs("job without cells or domain_dp\n", stderr);
    return 2;
  }
  const double h = cbrt(domain[0] * domain[1] * domain[2] / (cells[0] * cells[1] * cells[2]));
  char tmp[4096];
  snprintf(tmp, sizeof tmp, "%s.tmp", result);
  FILE* out = fopen(tmp, "w");
  if (!out) {
    perror(tmp);
    return 1;
  }
  fprintf(out,
          "{\"schema\":\"gridfree/result/1\",\"job_hash\":\"fake\",\"status\":\"converged\",\"reason\":\"\","
          "\"srq\":{\"dp_star\":%.12g},\"grid\":{\"cells\":[%d,%d,%d],\"delta_star\":%.15g},"
          "\"iterations\":7,\"timing\":{\"wall_s\":0.01,\"cpu_s\":0.01},\"memory\":{\"peak_rss_mb\":1},"
          "\"version\":\"fake\"}\n",
          1159 + h, (int)cells[0], (int)cells[1], (int)cells[2], h);
  if (fclose(out) != 0 || rename(tmp, result) != 0) {
    perror(result);
    return 1;
  }
  return log_invocation(result);
}
