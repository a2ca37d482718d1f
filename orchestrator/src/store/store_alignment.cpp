// SPDX-License-Identifier: GPL-3.0-or-later
// Store side of the alignment check and the series' transfer columns (store_alignment.h).
#include "store/store_alignment.h"

#include <map>

namespace gridfree {

void store_series_transfer(Database& db, const std::vector<long long>& series_ids, const ExpandedStudy& ex) {
  auto up = db.prepare(
      "UPDATE series SET pre_deposition = ?, sampling = ?, integration = ?, diffusivity = ?, steps = ? WHERE id = ?");
  for (std::size_t i = 0; i < series_ids.size() && i < ex.transfer.size(); ++i) {
    const TransferColumns& t = ex.transfer[i];
    up.reset();
    up.bind_all(t.pre_deposition, t.sampling, t.integration, t.diffusivity, t.steps, series_ids[i]).run();
  }
}

std::size_t store_alignment_jobs(Database& db, long long study_id, const std::vector<long long>& series_ids,
                                 const ExpandedStudy& ex) {
  if (ex.alignment.empty()) return 0;
  std::size_t inserted = 0;
  auto ins_job = db.prepare(
      "INSERT OR IGNORE INTO jobs(job_hash, spec_json, nx, ny, nz, cells, delta_star) VALUES (?, ?, ?, ?, ?, ?, ?)");
  auto find_job = db.prepare("SELECT id FROM jobs WHERE job_hash = ?");
  auto requeue = db.prepare("UPDATE jobs SET status = 'queued', error = NULL WHERE id = ? AND status = 'cancelled'");
  auto link = db.prepare(
      "INSERT OR IGNORE INTO study_jobs(study_id, job_id, series_id, grid_index, alignment_only) VALUES (?, ?, ?, ?, 1)");
  auto record = db.prepare(
      "INSERT OR IGNORE INTO alignment_jobs(series_id, grid_index, job_id, base_job_id, dnx, dny, dnz) "
      "VALUES (?, ?, ?, ?, ?, ?, ?)");
  auto id_of = [&](const std::string& hash) {
    find_job.reset();
    find_job.bind_all(hash);
    find_job.step();
    return find_job.as_int(0);
  };
  for (const AlignmentJob& a : ex.alignment) {
    const long long series = series_ids.at(a.series);
    const long long cells = static_cast<long long>(a.cells[0]) * a.cells[1] * a.cells[2];
    ins_job.reset();
    ins_job.bind_all(a.hash, a.doc.dump(), a.cells[0], a.cells[1], a.cells[2], cells, a.delta_star).run();
    if (db.changes() > 0) ++inserted;
    const long long job = id_of(a.hash), base = id_of(a.base_hash);
    requeue.reset();
    requeue.bind_all(job).run();
    link.reset();
    link.bind_all(study_id, job, series, static_cast<long long>(a.grid)).run();
    record.reset();
    record.bind_all(series, static_cast<long long>(a.grid), base, base, 0, 0, 0).run();
    record.reset();
    record.bind_all(series, static_cast<long long>(a.grid), job, base, a.offsets[0], a.offsets[1], a.offsets[2]).run();
  }
  return inserted;
}

std::vector<AlignmentValues> alignment_values(Database& db, long long study_id) {
  std::vector<AlignmentValues> out;
  auto st = db.prepare(
      "SELECT a.series_id, a.grid_index, COALESCE(br.delta_star, bj.delta_star), bj.nx, bj.ny, bj.nz, "
      "CASE WHEN r.status = 'converged' THEN r.dp_star END "
      "FROM alignment_jobs a JOIN series se ON se.id = a.series_id JOIN jobs bj ON bj.id = a.base_job_id "
      "LEFT JOIN results br ON br.job_id = a.base_job_id LEFT JOIN results r ON r.job_id = a.job_id "
      "WHERE se.study_id = ? ORDER BY se.position, a.grid_index, a.job_id <> a.base_job_id, a.dny, a.dnx, a.dnz");
  st.bind_all(study_id);
  while (st.step()) {
    const long long series = st.as_int(0);
    const int grid = static_cast<int>(st.as_int(1));
    if (out.empty() || out.back().series_id != series || out.back().grid_index != grid) {
      AlignmentValues v;
      v.series_id = series;
      v.grid_index = grid;
      v.delta_star = st.as_double(2);
      v.cells = {static_cast<int>(st.as_int(3)), static_cast<int>(st.as_int(4)), static_cast<int>(st.as_int(5))};
      out.push_back(v);
    }
    out.back().dp_star.push_back(st.as_opt_double(6));
  }
  return out;
}

std::vector<AlignmentRow> alignment_rows(Database& db, long long study_id) {
  std::vector<AlignmentRow> out;
  auto st = db.prepare(
      "SELECT v.series_id, v.grid_index, v.nx, v.ny, v.nz, v.delta_star, v.variants, v.converged, "
      "v.dp_star_min, v.dp_star_max, v.dp_star_mean, v.spread, v.f, v.u "
      "FROM v_alignment v JOIN series se ON se.id = v.series_id "
      "WHERE se.study_id = ? ORDER BY se.position, v.grid_index");
  st.bind_all(study_id);
  while (st.step()) {
    AlignmentRow r;
    r.series_id = st.as_int(0);
    r.grid_index = static_cast<int>(st.as_int(1));
    r.cells = {static_cast<int>(st.as_int(2)), static_cast<int>(st.as_int(3)), static_cast<int>(st.as_int(4))};
    r.delta_star = st.as_double(5);
    r.variants = static_cast<int>(st.as_int(6));
    r.converged = static_cast<int>(st.as_int(7));
    r.dp_min = st.as_opt_double(8);
    r.dp_max = st.as_opt_double(9);
    r.dp_mean = st.as_opt_double(10);
    r.spread = st.as_opt_double(11);
    r.f = st.as_opt_double(12);
    r.u = st.as_opt_double(13);
    out.push_back(r);
  }
  return out;
}

}  // namespace gridfree
