"""The planar MuJoCo models of the validation (mujoco_tower.py, mujoco_stack.py):
a church on a horizontal slide joint (or fixed), and blocks standing on it,
each on slide-x, slide-z and hinge joints relative to the body below,
touching it at two spheres of radius RHO (or `rho`) at its base corners, with
stiff contacts (time constant tc: MuJoCo's contact is a spring of natural
frequency 1/tc and damping ratio `damping`, critically damped unless told)
and friction high enough that no block slides."""

G = 9.81
RHO = 1e-3  # m, radius of the corner spheres


def solref(tc, damping=1.0):
    """MuJoCo's solref of a contact of stiffness 1/tc^2 (per unit of its effective
    mass) and damping ratio `damping`: MuJoCo's (timeconst, dampratio) gives the
    stiffness 1/(timeconst dampratio)^2 and the damping 2/timeconst, so the
    timeconst is tc/damping."""
    return f"{tc!r} 1" if damping == 1.0 else f"{tc / damping!r} {damping!r}"


def model(tc, dt, church_mass, mu, total_mass, blocks, damping=1.0):
    """The MJCF text: `mu` None for a fixed church, else the dry friction of its
    joint is mu total_mass g (the constant normal force); `blocks` is the nested
    body text of block(...); `damping` the damping ratio of the blocks' contacts."""
    friction = "" if mu is None else f'frictionloss="{mu * total_mass * G!r}" solreffriction="{tc!r} 1" solimpfriction="0.99 0.99 0.001"'
    joint = "" if mu is None else f'<joint name="u" type="slide" axis="1 0 0" {friction}/>'
    return f"""<mujoco>
<option timestep="{dt!r}" gravity="0 0 {-G!r}" cone="elliptic" integrator="implicitfast">
  <flag filterparent="disable"/>
</option>
<default><geom solref="{solref(tc, damping)}" solimp="0.99 0.99 0.001" friction="10 0.005 0.0001"/></default>
<worldbody>
 <body name="building">
  {joint}
  <geom name="church" type="box" size="20 5 5" pos="0 0 -5" mass="{church_mass!r}"/>
{blocks} </body>
</worldbody></mujoco>"""


def block(name, suffix, width, height, mass, pos=0.0, collision="", above="", rho=RHO):
    """A block `name` of width x height x width, its joints and corner spheres
    named x/z/theta/left/right + suffix, standing at height `pos` of the body
    below; `collision` (e.g. ' contype="2" conaffinity="2"') chooses what its
    corners touch; `above` is its top plate and the blocks on it; `rho` the
    radius of its corner spheres."""
    b, h = width / 2, height / 2
    at = f' pos="0 0 {pos!r}"' if pos else ""
    return f"""  <body name="{name}"{at}>
   <joint name="x{suffix}" type="slide" axis="1 0 0"/>
   <joint name="z{suffix}" type="slide" axis="0 0 1"/>
   <joint name="theta{suffix}" type="hinge" axis="0 1 0"/>
   <geom type="box" size="{b!r} {b!r} {h!r}" pos="0 0 {h!r}" mass="{mass!r}" contype="0" conaffinity="0"/>
   <geom name="left{suffix}" type="sphere" size="{rho!r}" pos="{-b + rho!r} 0 {rho!r}" mass="0.001"{collision}/>
   <geom name="right{suffix}" type="sphere" size="{rho!r}" pos="{b - rho!r} 0 {rho!r}" mass="0.001"{collision}/>
{above}  </body>
"""


def plate(width, height, thickness=0.01):
    """A thin plate at the top of a block, which the corners of the block above touch."""
    b = width / 2
    return f'   <geom name="plate" type="box" size="{b!r} {b!r} {thickness!r}" pos="0 0 {height - thickness!r}" mass="0.001" contype="2" conaffinity="2"/>\n'
