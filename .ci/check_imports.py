"""Import circles between the files of one folder of src/ (a file that uses an item of a sibling
which uses an item of it), read from the paths in the code (`use` and inline `crate::`,
`super::`, `self::` paths; comments and test modules left out). Exits 1 on any circle that is
not listed in KNOWN, printing the pair and one path each way.

    python3 .ci/check_imports.py
"""
import re,os,sys
files={}
for d,_,fs in os.walk('src'):
    for f in fs:
        if f.endswith('.rs'): files[os.path.join(d,f)]=open(os.path.join(d,f)).read()
def modpath(p):
    parts=p[len('src/'):-3].split('/')
    if parts[-1] in ('mod','lib','main'): parts=parts[:-1]
    return tuple(parts)
mods={}
for p in files: mods.setdefault(modpath(p),p)
def resolve(cur, path):
    segs=path.split('::')
    if segs[0]=='crate': base=[]; segs=segs[1:]
    elif segs[0]=='super':
        base=list(cur[:-1]); segs=segs[1:]
        while segs and segs[0]=='super': base=base[:-1]; segs=segs[1:]
    elif segs[0]=='self': base=list(cur); segs=segs[1:]
    else: return None
    best=None
    for k in range(len(segs)+1):
        t=tuple(base+segs[:k])
        if t in mods: best=t
    return best
edges={}
for p,s in files.items():
    if p.endswith('tests.rs') or '_tests.rs' in p or '/tests_' in p: continue
    cur=modpath(p)
    s=re.sub(r'(?s)#\[cfg\(test\)\]\s*(?:#\[path[^\]]*\]\s*)?(?:pub(?:\(crate\))? )?mod tests \{.*','',s)
    code='\n'.join(l for l in s.split('\n') if not l.strip().startswith('//'))
    for m in re.finditer(r'\b((?:crate|super|self)(?:::\w+)*)::\{([^}]*)\}', code):
        for item in m.group(2).split(','):
            item=item.strip().split(' ')[0]
            if item:
                t=resolve(cur, m.group(1)+'::'+item)
                if t and t!=cur and t[:-1]==cur[:-1] and len(t)==len(cur): edges.setdefault((cur,t),m.group(0))
    for m in re.finditer(r'\b((?:crate|super|self)(?:::\w+)+)', code):
        t=resolve(cur, m.group(1))
        if t and t!=cur and len(t)==len(cur) and t[:-1]==cur[:-1]:
            edges.setdefault((cur,t),m.group(1))
cyc=sorted((a,b) for (a,b) in edges if (b,a) in edges and a<b)
# Circles accepted for now, as ("a::b", "a::c") pairs: none.
KNOWN: set = set()
new = [(a, b) for a, b in cyc if ("::".join(a), "::".join(b)) not in KNOWN]
for a, b in cyc:
    mark = "known" if (a, b) not in new else "NEW"
    print(mark, "::".join(a), "<->", "::".join(b), "|", edges[(a, b)], "|", edges[(b, a)])
print(f"{len(cyc)} two-file circles, {len(new)} not known")
sys.exit(1 if new else 0)
