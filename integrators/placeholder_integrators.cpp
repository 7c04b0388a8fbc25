// placeholder until the integrators stage lands; removed with it
