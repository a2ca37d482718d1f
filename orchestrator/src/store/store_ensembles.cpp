// SPDX-License-Identifier: GPL-3.0-or-later
// Ensembles rows of a study (see store_ensembles.h).
#include "store/store_ensembles.h"

namespace gridfree {

void insert_ensembles(Database& db, long long study_id, const Ensembles& ensembles) {
  auto ins = db.prepare("INSERT INTO ensembles(study_id, name, case_name) VALUES (?, ?, ?)");
  for (const auto& [name, cases] : ensembles) {
    for (const auto& c : cases) {
      ins.reset();
      ins.bind_all(study_id, name, c).run();
    }
  }
}

Ensembles study_ensembles(Database& db, long long study_id) {
  Ensembles out;
  auto st = db.prepare("SELECT name, case_name FROM ensembles WHERE study_id = ? ORDER BY name, rowid");
  st.bind_all(study_id);
  while (st.step()) out[st.as_text(0)].push_back(st.as_text(1));
  return out;
}

}  // namespace gridfree
