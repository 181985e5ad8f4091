# Shell element sources (issue 3): target_sources(boltnet PRIVATE ...).
