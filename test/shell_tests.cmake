# Shell element tests (issue 3).
