# SPDX-License-Identifier: GPL-3.0-or-later
"""The text of a corpus file (corpus/README.md): the source's fields indented,
then one series per line, so a diff shows which series changed."""
import json


def corpus_text(doc):
    head = json.dumps({k: v for k, v in doc.items() if k != "series"}, indent=1, ensure_ascii=False)[:-2]
    rows = ",\n".join("  " + json.dumps(s, ensure_ascii=False) for s in doc["series"])
    return head + ',\n "series": [\n' + rows + "\n ]\n}\n"
