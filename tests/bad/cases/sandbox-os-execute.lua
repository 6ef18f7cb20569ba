-- expect: 1 "'os' is not available to figure scripts"
-- os.execute
os.execute('touch /tmp/curvefig-escaped')
