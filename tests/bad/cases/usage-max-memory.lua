-- expect: 2 "--max-memory '0': give MiB from 1 to 65536"
-- --max-memory 0
-- args: --max-memory 0
figure{ name = 'z' }
