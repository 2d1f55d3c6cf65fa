#!/usr/bin/python3
# Time to equal error of the dispersive Navarro eye against the monochromatic one (docs/spectral.md,
# "The dispersive eye"): relMSE in linear sRGB against each camera's own 2048-spp render, fitted
# over 16-128 spp, extrapolated to relMSE 1e-3. Run from anywhere after building build/bin/eyetrace;
# writes its renders into the current directory. Takes about 2 minutes on 2 cores.
import subprocess, time, numpy as np, OpenImageIO as oiio, sys, math
import os
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
B = os.path.join(ROOT, "build/bin/eyetrace"); S = os.path.join(ROOT, "scenes/peripheral.pbrt")
cams={"mono":'Camera "navarro" "float fov" 60 "float pupildiameter" 3 "float wavelength" 555',
      "disp":'Camera "navarro" "float fov" 60 "float pupildiameter" 3'}
def render(cam, spp, out, seed=1):
    t=time.process_time(); t0=time.time()
    r=subprocess.run([B,"render",S,"-o",out,"--spp",str(spp),"--resolution","150x100","--quiet","--threads","2","--seed",str(seed),"--camera",cams[cam],"--stats",out+".json"],check=True)
    import json; st=json.load(open(out+".json"))
    return st["render_seconds"]
def read(p): return oiio.ImageBuf(p).get_pixels(oiio.FLOAT)[:,:,:3]
res={}
for cam in cams:
    render(cam, 2048, f"{cam}_ref.exr", seed=99)
    ref=read(f"{cam}_ref.exr"); m=ref.mean()
    for spp in [16,32,64,128]:
        sec=render(cam, spp, f"{cam}_{spp}.exr")
        img=read(f"{cam}_{spp}.exr")
        rel=float(((img-ref)**2).mean()/(m*m))
        res.setdefault(cam,[]).append((spp,sec,rel)); print(cam,spp,sec,rel,flush=True)
# time to relMSE 1e-3 by log-log fit
out={}
for cam,v in res.items():
    s=np.log([x[0] for x in v]); e=np.log([x[2] for x in v]); k,c=np.polyfit(s,e,1)
    spp_t=math.exp((math.log(1e-3)-c)/k); sec_per_spp=np.mean([x[1]/x[0] for x in v])
    out[cam]=(spp_t, spp_t*sec_per_spp, k); print(cam,"slope",k,"spp@1e-3",spp_t,"sec",spp_t*sec_per_spp)
print("ratio disp/mono time at relMSE 1e-3:", out["disp"][1]/out["mono"][1])
