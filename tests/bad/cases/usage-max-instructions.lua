-- expect: 2 "--max-instructions '-5': give a number from 10000 to 1e15"
-- --max-instructions -5
-- args: --max-instructions -5
figure{ name = 'z' }
