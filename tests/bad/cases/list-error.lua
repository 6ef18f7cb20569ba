-- expect: 1 "stop listing"
-- the list command on a failing script
-- command: list
figure{ name = 'a' }
error('stop listing')
