-- expect: 1 "attempt to index a nil value (global 'os')"
-- os.execute
os.execute('touch /tmp/curvefig-escaped')
