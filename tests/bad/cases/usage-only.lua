-- expect: 2 "defines no figure named 'nothere'"
-- --only a figure that does not exist
-- args: --only nothere
figure{ name = 'z' }
