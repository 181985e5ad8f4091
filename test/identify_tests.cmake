# Identification tests (issue 5).
