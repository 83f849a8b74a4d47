-- Counts how often its body runs (must be once).
load_count = (load_count or 0) + 1
return { n = load_count }
