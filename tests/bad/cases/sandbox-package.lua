-- expect: 1 "'package' is not available to figure scripts"
-- package.loadlib
package.loadlib('/lib/x86_64-linux-gnu/libc.so.6', 'system')
