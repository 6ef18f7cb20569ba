-- expect: 1 "theme: redundant"
-- redundant takes true or false only
theme{ redundant = "yes" }
