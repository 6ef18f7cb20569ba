-- must stop: os is not in the sandbox
os.execute("touch hostile-was-here")
