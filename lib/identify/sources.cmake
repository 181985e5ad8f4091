# Joint parameter identification sources (issue 5): target_sources(boltnet PRIVATE ...).
