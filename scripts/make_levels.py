#!/usr/bin/env python3
"""Builds the parking levels (assets/scenes/levels/*.json) and their golden replays
(assets/replays/level-*.replay) from scripted manoeuvres.

Each manoeuvre is a list of (KEYS, until) steps: `until` is a frame count, or a condition on the
trace row (heading reached, speed through zero, ...) that cardemo finds by running the replay so
far with --trace. A pedal held through a stop holds the car (docs/controls.md), so a manoeuvre
that brakes and then drives the other way lets go for one frame in between (('.', 1)); the
steering ramp needs no fixed holds, since the turns run until their heading is reached. The
manoeuvre is first driven in an empty scene from the origin; the level is then built around its
end pose (the bay where the car stops, the player's start that distance before it), so the replay
parks whatever the car physics. Run it again after a physics change and re-check the hits and
parked frames it prints. Each level's par is the parked time of its human-tempo replay
(assets/replays/LEVEL.human.replay, made by scripts/make_human_replays.py) rounded up to whole
seconds; after a change that moves the levels, run this, then make_human_replays.py, then this
again.

usage: scripts/make_levels.py CARDEMO_BINARY [LEVEL_NUMBER...]
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "assets")
CARDEMO = None
TMP = None    # a temporary folder, made by main() (or by a script that imports this one)
EMPTY = None  # the empty scene the manoeuvres are first driven in, in TMP
ONLY = []
MAX_SPEED = 5.5  # m/s (about 20 km/h): parking levels are slow
PLAYER_LENGTH, PLAYER_WIDTH = 4.5, 1.8  # m


def run(scene, inputs):
    path = os.path.join(TMP, "m.replay")
    with open(path, "w") as f:
        f.write("cardemo-replay 1\nscene %s\nhz 120\n%s\n" % (scene, "\n".join(inputs)))
    trace = os.path.join(TMP, "m.csv")
    subprocess.run([CARDEMO, "replay", path, "--trace", trace], capture_output=True, check=True)
    with open(trace) as f:
        return list(csv.DictReader(f))


def f(row, key):
    return float(row[key])


def plan(steps, tail=60):
    """Frame counts for `steps`. A step is (KEYS, N frames), (KEYS, until) or
    (("KEYS", n), ("KEYS", m), until): the two runs repeated (a pedal pulsed to hold a slow
    speed against engine braking) until the condition holds."""
    fixed = []

    def first(keys, limit, until):
        rows = run(EMPTY, fixed + ["%d %s" % (limit, keys)])
        n = sum(int(s.split()[0]) for s in fixed)
        return next((i - n for i in range(n + 1, len(rows)) if until(rows[i])), None)

    for step in steps:
        if len(step) == 3:
            (a, na), (b, nb), until = step
            for _ in range(200):
                k = first(a, na, until)
                if k is not None:
                    fixed.append("%d %s" % (k, a))
                    break
                fixed.append("%d %s" % (na, a))
                k = first(b, nb, until)
                if k is not None:
                    fixed.append("%d %s" % (k, b))
                    break
                fixed.append("%d %s" % (nb, b))
            else:
                sys.exit("make_levels: pulses of %s/%s never meet their condition" % (a, b))
            continue
        keys, until = step
        if isinstance(until, int):
            fixed.append("%d %s" % (until, keys))
            continue
        k = first(keys, 3000, until)
        if k is None:
            sys.exit("make_levels: %s never meets its condition after %s" % (keys, fixed))
        fixed.append("%d %s" % (k, keys))
    fixed.append("%d ." % tail)
    return fixed, run(EMPTY, fixed)

def box(cx,cy,hx,hy):  # axis-aligned rectangle polygon, half extents
    return [[r(cx-hx),r(cy-hy)],[r(cx+hx),r(cy-hy)],[r(cx+hx),r(cy+hy)],[r(cx-hx),r(cy+hy)]]
def r(v): return round(v,3)
def car(i,x,y,h): return {"id":i,"x":r(x),"y":r(y),"heading_deg":h,"length":4.4,"width":1.8}
def line(a,b,w=0.12): return {"type":"line","from":[r(a[0]),r(a[1])],"to":[r(b[0]),r(b[1])],"width":w}
def arrow(a,b): return {"type":"arrow","from":[r(a[0]),r(a[1])],"to":[r(b[0]),r(b[1])],"width":0.3}

def scene(name, order, title, task, start, bay, goal, parked, obstacles, markings, bounds):
    g={"bay":{"x":r(bay[0]),"y":r(bay[1]),"heading_deg":bay[2],"length":bay[3],"width":bay[4]}}
    g.update(goal)
    return {"format":"cardemo-scene/1","name":name,"level":{"order":order,"title":title,"task":task},
            "bounds":{"min":bounds[0],"max":bounds[1]},
            "player":{"x":r(start[0]),"y":r(start[1]),"heading_deg":0,"length":PLAYER_LENGTH,"width":PLAYER_WIDTH,"health":100,"max_speed":MAX_SPEED},
            "goal":g,"parked":parked,"obstacles":obstacles,"markings":markings}

def dump(obj):
    # one line per array element for readability
    lines=['{']
    items=list(obj.items())
    for k,(key,v) in enumerate(items):
        comma=',' if k<len(items)-1 else ''
        if isinstance(v,list):
            lines.append('  "%s": ['%key)
            for j,e in enumerate(v):
                lines.append('    '+json.dumps(e)+(',' if j<len(v)-1 else ''))
            lines.append('  ]'+comma)
        else:
            lines.append('  "%s": %s%s'%(key,json.dumps(v),comma))
    lines.append('}')
    return '\n'.join(lines)+'\n'

def corners(rows, S):
    """The player's corners in every frame of a manoeuvre started at S."""
    hl,hw=PLAYER_LENGTH/2,PLAYER_WIDTH/2
    out=[]
    for row in rows:
        x,y,h=S[0]+f(row,'x'),S[1]+f(row,'y'),math.radians(f(row,'heading_deg'))
        c,s=math.cos(h),math.sin(h)
        for u,v in ((hl,hw),(hl,-hw),(-hl,hw),(-hl,-hw)):
            out.append((x+u*c-v*s,y+u*s+v*c))
    return out

def build(lv):
    fx,rows=plan(lv['steps'])
    end=rows[-1]
    D=(f(end,'x'),f(end,'y')); H=f(end,'heading_deg')
    B=lv['bay']
    S=(B[0]-D[0],B[1]-D[1])
    # The level around its start S and bay B; rows, the manoeuvre's trace, places the slalom's
    # bollards and the dead end's kerbs (levels 1-4 need only S and B).
    sc=lv['make'](S,B,rows)
    path='%s/scenes/levels/%s.json'%(OUT,lv['file'])
    open(path,'w').write(dump(sc))
    # The par: the level's human-tempo replay's parked time, rounded up (make_human_replays.py).
    par=human_par(lv['file'])
    if par is None:
        print('make_levels: %s: its human replay is missing or does not park; par left at %s s '
              '(run scripts/make_human_replays.py, then this again)'%(lv['file'],sc['goal']['par_time']))
    else:
        if par>sc['goal']['time_limit']:
            sys.exit('make_levels: %s: par %d s from its human replay exceeds its time limit'%(lv['file'],par))
        sc['goal']['par_time']=par
        open(path,'w').write(dump(sc))
    rp='%s/replays/%s.replay'%(OUT,lv['file'])
    body='cardemo-replay 1\n# %s\nscene ../scenes/levels/%s.json\nhz 120\n%s\n'%(lv['comment'],lv['file'],'\n'.join(fx))
    open(rp,'w').write(body)
    out=subprocess.run([CARDEMO,'replay',rp,'--print-expect'],capture_output=True,text=True)
    exp=[l for l in out.stdout.splitlines() if l.startswith('expect')]
    print(out.stdout + out.stderr)
    # The tail of stopped frames must outlast the goal's hold time (0.5 s by default), or the
    # replay never parks.
    if 'expect parked never' in exp:
        sys.exit('make_levels: %s never parks; lengthen its tail of stopped frames' % rp)
    open(rp,'w').write(body+'# Expectations (regenerate with: cardemo replay THIS --print-expect)\n'+'\n'.join(exp)+'\n')

def human_par(name):
    """The parked time of assets/replays/NAME.human.replay rounded up to whole seconds, or None
    when there is no such replay or it does not park."""
    rp='%s/replays/%s.human.replay'%(OUT,name)
    if not os.path.exists(rp):
        return None
    out=subprocess.run([CARDEMO,'replay',rp,'--json','-'],capture_output=True,text=True)
    if out.returncode not in (0,1):
        return None
    score=json.loads(out.stdout)['score']
    return None if score is None else math.ceil(score['seconds'])

def bay_between_cars(bx,by):
    """The bay of levels 1 and 5, facing +x: two cars on each side, bay lines, a wall behind."""
    parked=[car('N1',bx,by+2.6,0),car('N2',bx,by+5.2,180),car('S1',bx,by-2.6,180),car('S2',bx,by-5.2,0)]
    wall={"id":"back-wall","points":box(bx+3.55,by,0.2,8.0)}
    mk=[line((bx-2.75,by+y),(bx+2.75,by+y)) for y in (-6.5,-3.9,-1.3,1.3,3.9,6.5)]
    mk.append(line((bx+2.75,by-6.5),(bx+2.75,by+6.5)))
    return parked,wall,mk

def make1(S,B,rows):
    bx,by=B[0],B[1]
    parked,wall,mk=bay_between_cars(bx,by)
    obstacles=[wall]
    mk.append(arrow((S[0]+4,S[1]),(S[0]+8,S[1])))
    return scene('level-1-straight',1,'Straight in',
      'Drive straight into the bay ahead, between the two cars, and stop short of the wall',
      S,(bx,by,0,5.5,2.6),
      {"position_tolerance":0.6,"heading_tolerance_deg":10,"max_speed":0.3,"par_time":12,"time_limit":60},
      parked,obstacles,mk,[[r(S[0]-6),by-10],[bx+6,by+10]])
LEVEL1={'file':'level-1-straight','bay':(0.0,0.0),'make':make1,'comment':'Level 1: drive straight into the bay ahead and stop.',
    'steps':[('U',lambda r:f(r,'x')>9),('.',30),('D',lambda r:f(r,'speed')<=0),('.',30)]}

def make2(S,B,rows):
    bx,by=B[0],B[1]
    parked=[car('W1',bx-2.7,by,270),car('W2',bx-5.4,by,90),car('E1',bx+2.7,by,90),car('E2',bx+5.4,by,270),
            car('X1',bx-4.0,S[1]-6.0,90),car('X2',bx+1.5,S[1]-6.0,270),car('X3',bx+6.8,S[1]-6.0,90)]
    obstacles=[{"id":"back-wall","points":box(bx,by+3.35,9.0,0.2)}]
    mk=[line((bx+x,by-2.75),(bx+x,by+2.75)) for x in (-6.75,-4.05,-1.35,1.35,4.05,6.75)]
    mk.append(arrow((S[0]-6,S[1]),(S[0]-2,S[1])))
    return scene('level-2-reverse',2,'Reverse bay',
      'Drive past, then reverse into the bay between the cars so that you end facing out',
      S,(bx,by,270,5.5,2.6),
      {"position_tolerance":0.5,"heading_tolerance_deg":8,"max_speed":0.3,"par_time":16,"time_limit":90},
      parked,obstacles,mk,[[r(S[0]-14),r(S[1]-10)],[bx+12,by+5]])
LEVEL2={'file':'level-2-reverse','bay':(0.0,5.0),'make':make2,'comment':'Level 2: drive past the bay, stop, reverse in on full left lock, straighten, stop.',
    'steps':[('U',100),('D',lambda r:f(r,'speed')<=0),('.',1),('DL',60),(('L',8),('DL',16),lambda r:f(r,'heading_deg')<-85.5),('.',lambda r:abs(f(r,'steer_deg'))<0.01),('D',40),('.',60),('U',lambda r:f(r,'speed')>=0),('.',30)]}

def make3(S,B,rows):
    bx,by=B[0],B[1]
    parked=[car('F1',bx+7.6,by,0),car('F2',bx+7.6+5.6,by,0),car('R1',bx-5.0,by,0),car('R2',bx-10.6,by,0),
            car('O1',bx-6.0,by+7.6,180),car('O2',bx+3.0,by+7.6,180)]
    obstacles=[{"id":"kerb","points":box(bx,by-1.8,16.0,0.2)},
               {"id":"building","points":box(bx,by+10.4,16.0,0.3)}]
    mk=[line((bx-13.8,by+1.2),(bx+13.8,by+1.2)),
        line((bx-2.75,by-1.2),(bx-2.75,by+1.2)),line((bx+7.6-2.25,by-1.2),(bx+7.6-2.25,by+1.2)),
        line((bx-13.8,by+6.4),(bx+13.8,by+6.4)),
        line((bx-13.8,by+3.8),(bx-11.8,by+3.8)),line((bx-9.8,by+3.8),(bx-7.8,by+3.8)),
        line((bx-5.8,by+3.8),(bx-3.8,by+3.8)),line((bx-1.8,by+3.8),(bx+0.2,by+3.8)),
        line((bx+2.2,by+3.8),(bx+4.2,by+3.8)),line((bx+6.2,by+3.8),(bx+8.2,by+3.8)),
        line((bx+10.2,by+3.8),(bx+12.2,by+3.8)),
        arrow((S[0]-4,S[1]),(S[0],S[1]))]
    return scene('level-3-parallel',3,'Parallel parking',
      'Parallel park in the gap between the two cars, against the kerb',
      S,(bx,by,0,5.5,2.2),
      {"position_tolerance":0.5,"heading_tolerance_deg":8,"max_speed":0.3,"par_time":16,"time_limit":120},
      parked,obstacles,mk,[[bx-16,by-2.5],[bx+16,by+11]])
LEVEL3={'file':'level-3-parallel','bay':(0.0,0.0),'make':make3,'comment':'Level 3: stop beside the front car, reverse on right lock, straighten, then left lock into the space.',
    'steps':[('U',90),('D',lambda r:f(r,'speed')<=0),('.',1),('DR',60),(('R',8),('DR',16),lambda r:f(r,'heading_deg')>42),('D',30),('.',20),('DL',20),(('L',8),('DL',16),lambda r:f(r,'heading_deg')<2.5),('U',lambda r:f(r,'speed')>=0),('.',30)]}

def make4(S,B,rows):
    bx,by=B[0],B[1]
    inner=1.25      # half the garage's inner width: 2.5 m for a 1.8 m car
    door=by-2.75    # door line; the back wall is 0.45 m behind the parked car's nose, so a car
                    # stopped by ramming it is 0.45 m off, outside the 0.3 m tolerance
    back=by+2.7
    obstacles=[{"id":"garage-left","points":box(bx-inner-0.15,(door+back)/2,0.15,(back-door)/2)},
               {"id":"garage-right","points":box(bx+inner+0.15,(door+back)/2,0.15,(back-door)/2)},
               {"id":"garage-back","points":box(bx,back+0.15,inner+0.3,0.15)},
               {"id":"next-garage-left","points":box(bx-4.0,(door+back)/2,1.6,(back-door)/2+0.15)},
               {"id":"next-garage-right","points":box(bx+4.0,(door+back)/2,1.6,(back-door)/2+0.15)},
               {"id":"hedge","points":box(((S[0]-10)+(bx+9))/2,S[1]-4.2,((bx+9)-(S[0]-10))/2,0.4)}]
    parked=[car('V1',S[0]-6,S[1]-2.0,0)]
    mk=[line((bx-inner,door),(bx+inner,door),0.2),
        line((bx,door-1.0),(bx,door-0.2),0.1),
        arrow((S[0]+1,S[1]-2.0),(S[0]+5,S[1]-2.0))]
    return scene('level-4-garage',4,'Tight garage',
      'Turn into the garage (0.35 m to spare each side) and stop before its back wall',
      S,(bx,by,90,5.25,2.5),
      {"position_tolerance":0.3,"heading_tolerance_deg":5,"max_speed":0.3,"par_time":14,"time_limit":90},
      parked,obstacles,mk,[[r(S[0]-10),r(S[1]-5)],[r(bx+9),r(back+1)]])
LEVEL4={'file':'level-4-garage','bay':(0.0,0.0),'make':make4,'comment':'Level 4: follow the lane, turn in on full left lock, straighten on the centre line, stop short of the back wall.',
    'steps':[('U',60),('.',30),(('L',16),('UL',8),lambda r:f(r,'heading_deg')>87.3),('.',lambda r:abs(f(r,'steer_deg'))<0.01),(('.',16),('U',8),lambda r:f(r,'y')>8.9),('D',lambda r:f(r,'speed')<=0),('.',30)]}

def bollard(cx,cy,radius=0.35):  # an octagon
    return [[r(cx+radius*math.cos(math.pi*(k+0.5)/4)),r(cy+radius*math.sin(math.pi*(k+0.5)/4))] for k in range(8)]

def make5(S,B,rows):
    bx,by=B[0],B[1]
    # The slalom's turning points: where the path's lateral offset peaks, before the bay's run-in.
    path=[(S[0]+f(q,'x'),S[1]+f(q,'y')) for q in rows]
    turns=[path[i] for i in range(1,len(path)-1)
           if path[i][0]<bx-8 and path[i][0]>S[0]+4 and
           (path[i][1]-path[i-1][1])*(path[i+1][1]-path[i][1])<0]
    mid=(max(p[1] for p in turns)+min(p[1] for p in turns))/2
    course=[c for c in corners(rows,S) if c[0]<bx-6]
    top=max(c[1] for c in course)+0.7
    bottom=min(c[1] for c in course)-0.7
    obstacles=[{"id":"bollard-%d"%(k+1),"points":bollard(x,mid)} for k,(x,_) in enumerate(turns)]
    # A gate from each bollard to the kerb on the side the weave passes it, crossed driving +x: a
    # straight drive passes every bollard on one side, so it misses a gate and never parks.
    gates=[]
    for k,(x,y) in enumerate(turns):
        left=y>mid
        edge=mid+0.35 if left else mid-0.35
        kerb=top if left else bottom
        gates.append({"name":"%s of bollard %d"%("left" if left else "right",k+1),
                      "line":[[r(x),r(edge)],[r(x),r(kerb)]],"direction_deg":0})
    obstacles+=[{"id":"kerb-north","points":box((S[0]-3+bx-5)/2,top+0.2,(bx-5-(S[0]-3))/2,0.2)},
                {"id":"kerb-south","points":box((S[0]-3+bx-5)/2,bottom-0.2,(bx-5-(S[0]-3))/2,0.2)}]
    parked,wall,mk=bay_between_cars(bx,by)
    obstacles.append(wall)
    mk.append(arrow((S[0]+3,S[1]),(S[0]+6,S[1])))
    return scene('level-5-slalom',5,'Slalom',
      'Weave between the bollards, left of the first, then brake into the bay at the end',
      S,(bx,by,0,5.5,2.6),
      {"position_tolerance":0.6,"heading_tolerance_deg":10,"max_speed":0.3,"par_time":12,"time_limit":60,
       "gates":gates},
      parked,obstacles,mk,[[r(S[0]-4),r(min(bottom,by)-8)],[bx+5,r(max(top,by)+8)]])
# Turns to 34 degrees: with the steering ramp each leg is longer, and the course must still fit a
# 1024 px wide window at the camera's closest fit (24 px/m).
LEVEL5={'file':'level-5-slalom','bay':(0.0,0.0),'make':make5,
    'comment':'Level 5: accelerate, full left and right lock in turn past three bollards, straighten, brake in the bay.',
    'steps':[('U',lambda q:f(q,'x')>1),('UL',lambda q:f(q,'heading_deg')>34),('UR',lambda q:f(q,'heading_deg')<-34),
             ('UL',lambda q:f(q,'heading_deg')>34),('UR',lambda q:f(q,'heading_deg')<-34),
             ('UL',lambda q:f(q,'heading_deg')>-7.5),('U',lambda q:abs(f(q,'steer_deg'))<0.01),
             ('D',lambda q:f(q,'speed')<=0),('.',30)]}

def make6(S,B,rows):
    bx,by=B[0],B[1]
    swept=corners(rows,S)
    top=max(c[1] for c in swept)+0.45
    bottom=min(c[1] for c in swept)-0.45
    end=max(c[0] for c in swept)+0.45
    mouth=bx-6
    obstacles=[{"id":"kerb-north","points":box((mouth+end)/2,top+0.2,(end-mouth)/2,0.2)},
               {"id":"kerb-south","points":box((mouth+end)/2,bottom-0.2,(end-mouth)/2,0.2)},
               {"id":"dead-end","points":box(end+0.2,(top+bottom)/2,0.2,(top-bottom)/2+0.4)}]
    # Parked along the north kerb, behind the start and clear of the box (the south side is the
    # car's: its rear swings there as it turns in).
    parked=[]
    x=S[0]-1.5
    while x-2.2>bx+3.2:
        parked.append(car('N%d'%(len(parked)+1),x,top-1.05,180))
        x-=5.2
    mk=[line((mouth,by-1.4),(mouth,by+1.4),0.2),
        arrow((S[0]+1,S[1]),(S[0]+5,S[1]))]
    return scene('level-6-turn',6,'Three-point turn',
      'Turn round in the dead end in three moves, then stop in the box at the street\'s mouth, facing out',
      S,(bx,by,180,5.5,2.6),
      {"position_tolerance":0.5,"heading_tolerance_deg":8,"max_speed":0.3,"par_time":20,"time_limit":120},
      parked,obstacles,mk,[[r(mouth-4),r(bottom-1)],[r(end+1),r(top+1)]])
LEVEL6={'file':'level-6-turn','bay':(0.0,0.0),'make':make6,
    'comment':'Level 6: forward on left lock to face the kerb, reverse on right lock, forward on left lock, straighten, drive out, stop.',
    'steps':[('U',50),('.',10),(('L',16),('UL',8),lambda q:f(q,'heading_deg')>80),('D',lambda q:f(q,'speed')<=0),
             ('.',1),('DR',30),(('R',12),('DR',12),lambda q:f(q,'heading_deg')>150),('U',lambda q:f(q,'speed')>=0),
             ('.',1),('UL',30),(('L',12),('UL',12),lambda q:abs(f(q,'heading_deg'))>177),('.',lambda q:abs(f(q,'steer_deg'))<0.01),
             ('U',lambda q:f(q,'x')<-10),('D',lambda q:f(q,'speed')<=0),('.',30)]}


def make7(S,B,rows):
    bx,by=B[0],B[1]
    # The alley: 2.6 m between its walls (0.4 m each side of the car), from 3 m past the start to
    # where the car's corners leave its lane on the turn out, with blocks out to the bounds on both
    # sides, so the alley is the only way through.
    half=1.3
    lane=[c for c in corners(rows,S) if abs(c[1]-S[1])>half-0.15]
    x0=S[0]+3.0
    x1=min(c[0] for c in lane)-0.3
    top=S[1]+8.0
    bottom=by-6.0
    obstacles=[{"id":"alley-north","points":box((x0+x1)/2,(S[1]+half+top)/2,(x1-x0)/2,(top-S[1]-half)/2)},
               {"id":"alley-south","points":box((x0+x1)/2,(S[1]-half+bottom)/2,(x1-x0)/2,(S[1]-half-bottom)/2)}]
    parked=[car('W1',bx-2.7,by,270),car('E1',bx+2.7,by,90)]
    gates=[{"name":"the alley","box":{"x":r((x0+x1)/2),"y":r(S[1]),"heading_deg":0,"length":r(x1-x0),"width":2*half},
            "direction_deg":0}]
    mk=[line((bx+x,by-2.75),(bx+x,by+2.75)) for x in (-1.35,1.35)]
    mk.append(arrow((S[0]-3,S[1]),(S[0],S[1])))
    return scene('level-7-alley',7,'Narrow alley',
      'Drive through the narrow alley without touching its walls, then turn right into the bay',
      S,(bx,by,270,5.5,2.6),
      {"position_tolerance":0.5,"heading_tolerance_deg":8,"max_speed":0.3,"par_time":16,"time_limit":90,
       "gates":gates},
      parked,obstacles,mk,[[r(S[0]-5),r(bottom)],[r(bx+8),r(top)]])
LEVEL7={'file':'level-7-alley','bay':(0.0,0.0),'make':make7,
    'comment':'Level 7: straight through the alley at the speed cap, right lock out of it, straighten, brake in the bay.',
    'steps':[('U',lambda q:f(q,'x')>24),('UR',lambda q:f(q,'heading_deg')<-60),('R',lambda q:f(q,'heading_deg')<-86),
             ('.',lambda q:abs(f(q,'steer_deg'))<0.01),('D',lambda q:f(q,'speed')<=0),('.',30)]}

def make8(S,B,rows):
    bx,by=B[0],B[1]
    # A row of bays at 45 degrees to the lane (herringbone), entered forwards turning right;
    # neighbours sit one bay width apart across their own heading: 2.6 / sin 45 along the row.
    h=-45.0
    d=(math.cos(math.radians(h)),math.sin(math.radians(h)))
    pitch=2.6/math.sin(math.radians(45))
    parked=[car('P%d'%(k+3 if k>0 else k+2),bx+k*pitch,by,h) for k in (-2,-1,1,2)]
    for i,c in enumerate(parked): c['id']='A%d'%(i+1)
    mk=[]
    for k in (-2.5,-1.5,-0.5,0.5,1.5,2.5):
        cx=bx+k*pitch
        mk.append(line((cx-d[0]*2.75,by-d[1]*2.75),(cx+d[0]*2.75,by+d[1]*2.75)))
    back=by-2.75*math.sin(math.radians(45))-1.6
    obstacles=[{"id":"back-wall","points":box(bx,back-0.2,3.5*pitch,0.2)}]
    mk.append(arrow((S[0]-3,S[1]),(S[0],S[1])))
    return scene('level-8-angled',8,'Angled bay',
      'Turn into the angled bay between the cars at its own slant and stop inside it',
      S,(bx,by,h,5.5,2.6),
      {"position_tolerance":0.5,"heading_tolerance_deg":6,"max_speed":0.3,"par_time":12,"time_limit":60},
      parked,obstacles,mk,[[r(S[0]-5),r(back-1)],[r(bx+4*pitch),r(S[1]+6)]])
LEVEL8={'file':'level-8-angled','bay':(0.0,0.0),'make':make8,
    'comment':'Level 8: along the lane, right lock to the bay\'s 45 degrees, straighten, roll in, brake.',
    'steps':[('U',lambda q:f(q,'x')>3),('.',30),(('R',16),('UR',8),lambda q:f(q,'heading_deg')<-38.5),
             ('.',lambda q:abs(f(q,'steer_deg'))<0.01),('U',40),('D',lambda q:f(q,'speed')<=0),('.',30)]}

def make9(S,B,rows):
    bx,by=B[0],B[1]
    # The bay lies across a line of traffic cones from the start: the only way in is round the
    # line's far end (a U-turn), so the cones run from behind the bay to just short of where the
    # car's swept corners come within 0.8 m of the line.
    ymid=(S[1]+by)/2
    swept=corners(rows,S)
    cones=[]
    x=min(S[0],bx)-6.0
    while all(abs(c[0]-x)>0.8 or abs(c[1]-ymid)>0.8 for c in swept):
        cones.append(x)
        x+=1.5
    obstacles=[{"id":"cone-%d"%(k+1),"points":bollard(cx,ymid,0.25)} for k,cx in enumerate(cones)]
    parked=[car('F1',bx-5.6,by,180)]
    top=max(c[1] for c in swept)+2.0
    bottom=min(c[1] for c in swept)-2.0
    mk=[line((bx+2.75,by-1.3),(bx+2.75,by+1.3)),line((bx-2.75,by-1.3),(bx-2.75,by+1.3)),
        arrow((S[0]-3,S[1]),(S[0],S[1]))]
    return scene('level-9-cones',9,'Behind the cones',
      'The bay is behind the line of cones: drive round its far end and back into the bay',
      S,(bx,by,180,5.5,2.6),
      {"position_tolerance":0.5,"heading_tolerance_deg":8,"max_speed":0.3,"par_time":16,"time_limit":90},
      parked,obstacles,mk,[[r(min(cones)-4),r(bottom)],[r(max(c[0] for c in swept)+3),r(top)]])
LEVEL9={'file':'level-9-cones','bay':(0.0,0.0),'make':make9,
    'comment':'Level 9: along the cones, full left lock round their end, straighten, back along them, brake in the bay.',
    'steps':[('U',lambda q:f(q,'x')>14),('UL',lambda q:f(q,'heading_deg')>174),('U',lambda q:abs(f(q,'steer_deg'))<0.01),
             ('U',lambda q:f(q,'x')<2),('D',lambda q:f(q,'speed')<=0),('.',30)]}

def first_stop(rows, hold=61):
    """Index of the first frame after the car has moved from which it stands for `hold` frames."""
    moved=False
    for i in range(1,len(rows)-hold):
        moved=moved or f(rows[i],'speed')!=0
        if moved and all(f(q,'speed')==0 for q in rows[i:i+hold]):
            return i
    sys.exit('make_levels: the chain never stops in its first bay')

def make10(S,B,rows):
    bx,by=B[0],B[1]
    # Bay A is where the manoeuvre first stands long enough to park (its hold), bay B where it
    # ends: a row of cars facing each other across the lane, nose-in bays on both sides.
    a=rows[first_stop(rows)]
    ax,ay=S[0]+f(a,'x'),S[1]+f(a,'y')
    parked=[car('N%d'%(k+1),ax+dx,ay,90) for k,dx in enumerate((-5.4,-2.7,2.7,5.4))]
    parked+=[car('S%d'%(k+1),bx+dx,by,270) for k,dx in enumerate((-5.4,-2.7,2.7,5.4))]
    north=ay+2.2+0.6
    south=by-2.2-0.6
    obstacles=[{"id":"north-wall","points":box((ax+bx)/2,north+0.2,(bx-ax)/2+9.0,0.2)},
               {"id":"south-wall","points":box((ax+bx)/2,south-0.2,(bx-ax)/2+9.0,0.2)}]
    mk=[line((ax+x,ay-2.75),(ax+x,ay+2.75)) for x in (-6.75,-4.05,-1.35,1.35,4.05,6.75)]
    mk+=[line((bx+x,by-2.75),(bx+x,by+2.75)) for x in (-6.75,-4.05,-1.35,1.35,4.05,6.75)]
    mk.append(arrow((S[0]-4,S[1]),(S[0]-1,S[1])))
    goal={"position_tolerance":0.5,"heading_tolerance_deg":8,"max_speed":0.3,"par_time":30,
          "time_limit":45,
          "next_bays":[{"x":r(bx),"y":r(by),"heading_deg":270,"length":5.5,"width":2.6}]}
    return scene('level-10-chain',10,'Two bays against the clock',
      'Park nose-in in bay 1, then in bay 2 across the lane, within the time limit',
      S,(ax,ay,90,5.5,2.6),goal,parked,obstacles,mk,
      [[r(S[0]-7),r(south-1)],[r(bx+9),r(north+1)]])
LEVEL10={'file':'level-10-chain','bay':(0.0,0.0),'make':make10,
    'comment':'Level 10: left lock nose-in into bay 1, stop; reverse out on left lock, drive on, right lock nose-in into bay 2, stop.',
    'steps':[('U',60),('.',30),(('L',16),('UL',8),lambda r:f(r,'heading_deg')>87.3),('.',lambda r:abs(f(r,'steer_deg'))<0.01),
             (('.',16),('U',8),lambda r:f(r,'y')>7.5),('D',lambda r:f(r,'speed')<=0),('.',75),
             ('D',40),(('L',8),('DL',16),lambda r:f(r,'heading_deg')<3),('.',lambda r:abs(f(r,'steer_deg'))<0.01),
             ('U',lambda r:f(r,'speed')>=0),('.',1),
             ('U',lambda r:f(r,'x')>12),('D',lambda r:f(r,'speed')<1.6),('.',1),
             (('R',16),('UR',8),lambda r:f(r,'heading_deg')<-87.3),('.',lambda r:abs(f(r,'steer_deg'))<0.01),
             (('.',16),('U',8),lambda r:f(r,'y')<-4),('D',lambda r:f(r,'speed')<=0),('.',30)]}

ALL_LEVELS = (LEVEL1, LEVEL2, LEVEL3, LEVEL4, LEVEL5, LEVEL6, LEVEL7, LEVEL8, LEVEL9, LEVEL10)


def main():
    global CARDEMO, ONLY, TMP, EMPTY
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    CARDEMO = os.path.abspath(sys.argv[1])
    ONLY = sys.argv[2:]
    TMP = tempfile.mkdtemp(prefix="cardemo-levels-")
    EMPTY = os.path.join(TMP, "empty.json")
    with open(EMPTY, "w") as f:
        json.dump({"format": "cardemo-scene/1", "name": "empty", "parked": [],
                   "player": {"x": 0, "y": 0, "heading_deg": 0, "length": PLAYER_LENGTH, "width": PLAYER_WIDTH,
                              "max_speed": MAX_SPEED}}, f)
    os.makedirs(os.path.join(OUT, "scenes", "levels"), exist_ok=True)
    try:
        for level in ALL_LEVELS:
            if ONLY and level["file"].split("-")[1] not in ONLY:
                continue
            build(level)
    finally:
        shutil.rmtree(TMP, ignore_errors=True)


if __name__ == "__main__":
    main()
